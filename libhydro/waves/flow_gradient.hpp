#pragma once
// The flow a load point feels and its gradient in position, for the loads' Jacobians
// (d f / d y = d f / d v . grad v + d f / d a . grad a). The flow is Sea::at's, taken at the
// surface point below a point that is above the local elevation (what a body whose centre is out
// of the water feels); its gradient is by central differences of that, with the step
// flowGradientStep(sea). The kink of that clamp at the surface is not smoothed: within one step
// of the surface the difference straddles it. Nor is a current's shear that is singular (a power
// law at the bed, where dU/dz is infinite) or kinked (a table's samples): near such a level the
// difference is an average over two steps.
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

// The difference step: 1e-4 of the shortest wave's 1 / k, or of the depth (1 m in deep water)
// when there is no wave, so that the truncation error is ~1e-9 of the gradient and round-off
// ~1e-12.
double flowGradientStep(const Sea& sea);

FlowGradient flowGradient(const Sea& sea, const Eigen::Vector3d& x, double t);

}  // namespace flexmoor::hydro
