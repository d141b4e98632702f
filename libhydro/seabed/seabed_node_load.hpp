#pragma once
// Seabed contact of a body at a node (seabed_contact.hpp, MoorDyn v2's spring-damper over a
// projected area): where the body's lowest point, `offset` below the node, is below the bed by
// delta (along the bed's normal), N = (k_b delta - c_b u'.n) A pushes it out along the normal,
// with friction along the bed (seabed_friction.hpp; the moordyn law's friction damping acts on the
// body as on one of MoorDyn's nodes). Nothing acts above the bed.
#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

class SeabedNodeLoad final : public model::NodeLoad {
 public:
  // area: the body's projected area on the bed (a sphere's pi D^2 / 4); offset: how far its
  // lowest point is below the node (a sphere's radius).
  SeabedNodeLoad(int node, Bathymetry bed, SeabedProperties properties, double area, double offset);

  int node() const override { return node_; }
  bool contact() const override { return true; }
  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override;

 private:
  int node_;
  Bathymetry bed_;
  SeabedProperties properties_;
  double area_, offset_;
};

}  // namespace flexmoor::hydro
