#pragma once
// The flow a load point feels and its gradient in position, for the loads' Jacobians
// (d f / d y = d f / d v . grad v + d f / d a . grad a). The flow is Sea::at's, taken at the
// surface point below a point that is above the local elevation (what a body whose centre is out
// of the water feels); its gradient is Sea's closed form (FluidGradient), for a point above the
// surface that of v(x, y, eta(x, y)): the chain rule through grad eta, nothing in z. The kink of
// that clamp at the surface is not smoothed: the gradient is that of the side the point is on.
#include <Eigen/Core>

#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {

struct FlowKinematics {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
};

struct FlowGradient {
  Eigen::Matrix3d velocity = Eigen::Matrix3d::Zero();      // d v / d y
  Eigen::Matrix3d acceleration = Eigen::Matrix3d::Zero();  // d a / d y
  Eigen::Vector3d elevation = Eigen::Vector3d::Zero();     // (d eta / dx, d eta / dy, 0)
};

// The flow at x, or at (x, y, eta) when x is above the surface.
FlowKinematics flowBelowSurface(const Sea& sea, const Eigen::Vector3d& x, double t);

FlowGradient flowGradient(const Sea& sea, const Eigen::Vector3d& x, double t);

}  // namespace flexmoor::hydro
