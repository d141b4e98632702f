#pragma once
// The quadratic drag kernel shared by lines and bodies: g(w) = |w| w and its derivative
// dg/dw = |w| I + w w^T / |w| (zero at w = 0, where g is once but not twice differentiable).
#include <Eigen/Core>

namespace flexmoor::hydro {

inline Eigen::Vector3d quadraticDrag(const Eigen::Vector3d& w) { return w.norm() * w; }

inline Eigen::Matrix3d quadraticDragDerivative(const Eigen::Vector3d& w) {
  const double s = w.norm();
  if (s == 0.0) return Eigen::Matrix3d::Zero();
  return s * Eigen::Matrix3d::Identity() + w * w.transpose() / s;
}

}  // namespace flexmoor::hydro
