#include "libhydro/seabed/seabed_node_load.hpp"

#include <utility>

#include "libhydro/seabed/seabed_point_force.hpp"

namespace flexmoor::hydro {

SeabedNodeLoad::SeabedNodeLoad(int node, Bathymetry bed, SeabedProperties properties, double area,
                               double offset)
    : node_(node), bed_(std::move(bed)), properties_(properties), area_(area), offset_(offset) {}

model::PointForce SeabedNodeLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  // From the body's lowest point; the contact law per unit length over a width is, over an
  // area, the force itself.
  const Eigen::Vector3d lowest = p.position - offset_ * Eigen::Vector3d::UnitZ();
  return seabedPointForce(seabedLoadAt(bed_, properties_, lowest, area_, p.velocity), jacobians);
}

}  // namespace flexmoor::hydro
