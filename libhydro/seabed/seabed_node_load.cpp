#include "libhydro/seabed/seabed_node_load.hpp"

#include <utility>

namespace flexmoor::hydro {

SeabedNodeLoad::SeabedNodeLoad(int node, Bathymetry bed, SeabedProperties properties, double area,
                               double offset)
    : node_(node), bed_(std::move(bed)), properties_(properties), area_(area), offset_(offset) {}

model::PointForce SeabedNodeLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  model::PointForce out;
  // From the body's lowest point; the contact law per unit length over a width is, over an
  // area, the force itself.
  const Eigen::Vector3d lowest = p.position - offset_ * Eigen::Vector3d::UnitZ();
  const SeabedPointLoad s = seabedLoadAt(bed_, properties_, lowest, area_, p.velocity);
  out.force = s.force;
  if (!jacobians) return out;
  out.d_position = s.d_position;
  out.d_velocity = s.d_velocity;
  return out;
}

}  // namespace flexmoor::hydro
