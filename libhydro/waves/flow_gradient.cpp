#include "libhydro/waves/flow_gradient.hpp"

#include <algorithm>

namespace flexmoor::hydro {

FlowKinematics flowBelowSurface(const Sea& sea, const Eigen::Vector3d& x, double t) {
  const double eta = sea.elevation(x, t);
  const FluidPoint f = sea.at(Eigen::Vector3d(x.x(), x.y(), std::min(x.z(), eta)), t);
  return {f.velocity, f.acceleration};
}

FlowGradient flowGradient(const Sea& sea, const Eigen::Vector3d& x, double t) {
  const double eta = sea.elevation(x, t);
  FluidGradient g;
  sea.at(Eigen::Vector3d(x.x(), x.y(), std::min(x.z(), eta)), t, g);
  FlowGradient out{g.velocity, g.acceleration, g.elevation};
  if (x.z() > eta) {
    // Above the surface: d/dy_j of v(x, y, eta(x, y)) = dv/dy_j + dv/dz deta/dy_j, none in z.
    for (int j = 0; j < 2; ++j) {
      out.velocity.col(j) += g.velocity.col(2) * g.elevation(j);
      out.acceleration.col(j) += g.acceleration.col(2) * g.elevation(j);
    }
    out.velocity.col(2).setZero();
    out.acceleration.col(2).setZero();
  }
  return out;
}

}  // namespace flexmoor::hydro
