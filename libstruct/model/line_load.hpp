#pragma once
// The load-point interface: how anything outside libstruct (libhydro's Morison loads, a wind
// model, a test) puts a distributed load on line elements. The cable element evaluates it at
// its integration points on the current configuration and integrates it with the shape
// functions (Eq. E.1, E.12). libstruct never includes a libhydro header.
#include <Eigen/Core>

namespace flexmoor::model {

struct LinePoint {
  Eigen::Vector3d position;      // current position y
  Eigen::Vector3d velocity;      // u'
  Eigen::Vector3d acceleration;  // u''
  Eigen::Vector3d tangent;       // unit tangent of the deformed axis
  double stretch = 1.0;          // current length / reference length
  double time = 0.0;
  int element = -1;  // index of the element in the model
};

class LineLoad {
 public:
  virtual ~LineLoad() = default;
  // Force per unit current (deformed) length at the point.
  virtual Eigen::Vector3d forcePerLength(const LinePoint& point) const = 0;
};

}  // namespace flexmoor::model
