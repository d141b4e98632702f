#include "tests/support/mooring_catenary.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace flexmoor::test {
namespace {

// The spans (x, z) that the forces (H, V_F) give (the equations in the header).
Eigen::Vector2d spans(const MooringLineInputs& in, double H, double V) {
  const double w = in.submerged_weight, L = in.unstretched_length, EA = in.axial_stiffness;
  const double on_seabed = L - V / w;
  if (on_seabed > 0.0)
    return {on_seabed + H / w * std::asinh(V / H) + H * L / EA,
            H / w * (std::sqrt(1.0 + (V / H) * (V / H)) - 1.0) + V * V / (2.0 * EA * w)};
  const double Va = V - w * L;  // vertical force at the anchor end
  return {H / w * (std::asinh(V / H) - std::asinh(Va / H)) + H * L / EA,
          H / w * (std::sqrt(1.0 + (V / H) * (V / H)) - std::sqrt(1.0 + (Va / H) * (Va / H))) +
              (V * L - 0.5 * w * L * L) / EA};
}

}  // namespace

double MooringLineSolution::fairlead_tension() const {
  return std::hypot(horizontal_force, fairlead_vertical);
}

MooringLineSolution solveMooringLine(const MooringLineInputs& in) {
  const Eigen::Vector2d target(in.horizontal_span, in.vertical_span);
  // Start: the weight of a suspended length equal to the vertical span, and a modest H.
  Eigen::Vector2d f(0.1 * in.submerged_weight * in.unstretched_length,
                    in.submerged_weight * in.vertical_span);
  for (int it = 0; it < 100; ++it) {
    const Eigen::Vector2d r = spans(in, f(0), f(1)) - target;
    if (r.norm() < 1e-12 * target.norm()) {
      MooringLineSolution s{f(0), f(1),
                            std::max(0.0, in.unstretched_length - f(1) / in.submerged_weight)};
      return s;
    }
    Eigen::Matrix2d J;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d h = Eigen::Vector2d::Zero();
      h(j) = 1e-7 * f(j);
      J.col(j) = (spans(in, f(0) + h(0), f(1) + h(1)) - spans(in, f(0) - h(0), f(1) - h(1))) /
                 (2.0 * h(j));
    }
    Eigen::Vector2d step = J.partialPivLu().solve(-r);
    // Keep H positive: halve a step that would make it negative.
    while (f(0) + step(0) <= 0.0) step *= 0.5;
    f += step;
  }
  throw std::runtime_error("solveMooringLine: Newton did not converge");
}

}  // namespace flexmoor::test
