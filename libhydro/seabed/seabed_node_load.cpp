#include "libhydro/seabed/seabed_node_load.hpp"

#include <utility>

namespace flexmoor::hydro {

SeabedNodeLoad::SeabedNodeLoad(int node, Bathymetry bed, SeabedProperties properties, double area,
                               double offset)
    : node_(node), bed_(std::move(bed)), properties_(properties), area_(area), offset_(offset) {}

model::PointForce SeabedNodeLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  model::PointForce out;
  const double x = p.position.x(), y = p.position.y();
  const Eigen::Vector3d n = bed_.normal(x, y);
  // As for a line point (seabed_line_load.cpp), from the body's lowest point; the contact law
  // per unit length over a width is, over an area, the force itself.
  const double delta = n.z() * (bed_.height(x, y) - (p.position.z() - offset_));
  const SeabedPointLoad s = seabedLoad(properties_, delta, n, area_, p.velocity);
  out.force = s.force;
  if (!jacobians) return out;
  out.d_position = s.d_position;
  out.d_velocity = s.d_velocity;
  return out;
}

}  // namespace flexmoor::hydro
