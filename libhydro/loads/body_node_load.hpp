#pragma once
// A point body (buoy, clump weight; point_body.hpp) at a node, in a sea, through libstruct's
// load-point interface: buoyancy of its submerged part, drag on the relative velocity,
// Froude-Krylov and added mass. Its mass and weight are the structure's (a point-mass element at
// the same node); this load is the water's part only.
#include <memory>

#include "libhydro/loads/point_body.hpp"
#include "libhydro/waves/sea.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

class BodyNodeLoad final : public model::NodeLoad {
 public:
  BodyNodeLoad(int node, PointBody body, std::shared_ptr<const Sea> sea);

  int node() const override { return node_; }
  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override;
  const PointBody& body() const { return body_; }

 private:
  int node_;
  PointBody body_;
  std::shared_ptr<const Sea> sea_;
  std::shared_ptr<const Sea>
      still_;  // sea_ without its waves, for static solves (LoadPoint::still)
};

}  // namespace flexmoor::hydro
