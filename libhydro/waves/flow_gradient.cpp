#include "libhydro/waves/flow_gradient.hpp"

#include <algorithm>
#include <cmath>

namespace flexmoor::hydro {

FlowKinematics flowBelowSurface(const Sea& sea, const Eigen::Vector3d& x, double t) {
  const double eta = sea.elevation(x, t);
  const FluidPoint f = sea.at(Eigen::Vector3d(x.x(), x.y(), std::min(x.z(), eta)), t);
  return {f.velocity, f.acceleration};
}

double flowGradientStep(const Sea& sea) {
  double k_max = 0.0;
  for (const WaveComponent& c : sea.components()) k_max = std::max(k_max, c.k);
  if (k_max > 0.0) return 1e-4 / k_max;
  const double depth = sea.water().depth;
  return 1e-4 * (std::isfinite(depth) && depth > 0.0 ? depth : 1.0);
}

FlowGradient flowGradient(const Sea& sea, const Eigen::Vector3d& x, double t) {
  const double h = flowGradientStep(sea);
  FlowGradient g;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = x, minus = x;
    plus(k) += h;
    minus(k) -= h;
    const FlowKinematics a = flowBelowSurface(sea, plus, t), b = flowBelowSurface(sea, minus, t);
    g.velocity.col(k) = (a.velocity - b.velocity) / (2.0 * h);
    g.acceleration.col(k) = (a.acceleration - b.acceleration) / (2.0 * h);
    if (k < 2) g.elevation(k) = (sea.elevation(plus, t) - sea.elevation(minus, t)) / (2.0 * h);
  }
  return g;
}

}  // namespace flexmoor::hydro
