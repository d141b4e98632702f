#include "libhydro/waves/flow_gradient.hpp"

namespace flexmoor::hydro {

// A wet point is evaluated once (Sea::at gives the elevation with the flow); only a point above
// the surface needs a second evaluation, at the surface below it.
FlowKinematics flowBelowSurface(const Sea& sea, const Eigen::Vector3d& x, double t) {
  FluidPoint f = sea.at(x, t);
  if (!f.wet) f = sea.at(Eigen::Vector3d(x.x(), x.y(), f.elevation), t);
  return {f.velocity, f.acceleration};
}

FlowGradient flowGradient(const Sea& sea, const Eigen::Vector3d& x, double t) {
  FluidGradient g;
  const FluidPoint f = sea.at(x, t, g);
  const double eta = f.elevation;
  if (!f.wet) sea.at(Eigen::Vector3d(x.x(), x.y(), eta), t, g);
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
