#include "libhydro/loads/body_node_load.hpp"

#include <utility>

#include "libhydro/waves/flow_gradient.hpp"

namespace flexmoor::hydro {

BodyNodeLoad::BodyNodeLoad(int node, PointBody body, std::shared_ptr<const Sea> sea)
    : node_(node),
      body_(body),
      sea_(std::move(sea)),
      still_(std::make_shared<const Sea>(sea_->stillWater())) {}

// The body's centre at p.position, depth = eta(x, y, t) - z; the flow is that at the centre, or
// at the surface point below it when the centre is out of the water (flow_gradient.hpp).
model::PointForce BodyNodeLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  const Sea& sea = p.still ? *still_ : *sea_;
  const Water& water = sea.water();
  const double depth = sea.elevation(p.position, p.time) - p.position.z();
  const FlowKinematics flow = flowBelowSurface(sea, p.position, p.time);
  const PointBodyLoad b = pointBodyLoad(body_, water.density, water.gravity, depth, p.velocity,
                                        p.acceleration, flow.velocity, flow.acceleration);
  model::PointForce out;
  out.force = b.force;
  if (!jacobians) return out;
  out.d_velocity = b.d_velocity;
  out.d_acceleration = b.d_acceleration;
  // d depth / d y = grad eta - e_z; the flow through its gradient.
  const FlowGradient g = flowGradient(sea, p.position, p.time);
  const Eigen::Vector3d d_depth = g.elevation - Eigen::Vector3d::UnitZ();
  out.d_position = b.d_depth * d_depth.transpose() + b.d_fluid_velocity * g.velocity +
                   b.d_fluid_acceleration * g.acceleration;
  return out;
}

}  // namespace flexmoor::hydro
