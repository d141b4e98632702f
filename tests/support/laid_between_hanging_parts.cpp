#include "tests/support/laid_between_hanging_parts.hpp"

#include <cmath>
#include <stdexcept>

#include "tests/support/scalar_root.hpp"

namespace flexmoor::test {
namespace {

struct Part {
  double x, z;
};

Part hangingPart(const LaidBetweenInputs& in, double H, double s) {
  const double w = in.submerged_weight, EA = in.axial_stiffness, u = w * s / H;
  return {H / w * std::asinh(u) + H * s / EA,
          H / w * (std::sqrt(1.0 + u * u) - 1.0) + w * s * s / (2.0 * EA)};
}

// The length that hangs from height h to its touchdown at H (z grows with s).
double partLength(const LaidBetweenInputs& in, double H, double h) {
  return findRoot([&](double s) { return hangingPart(in, H, s).z - h; }, 0.0,
                  in.unstretched_length + h);
}

}  // namespace

double LaidBetweenSolution::fairleadTension() const {
  return std::hypot(horizontal_force, weight * fairlead_part);
}
double LaidBetweenSolution::anchorTension() const {
  return std::hypot(horizontal_force, weight * anchor_part);
}

LaidBetweenSolution solveLaidBetween(const LaidBetweenInputs& in) {
  const double L = in.unstretched_length, w = in.submerged_weight;
  const auto laid = [&](double H) {
    return L - partLength(in, H, in.anchor_height) - partLength(in, H, in.fairlead_height);
  };
  const auto span = [&](double H) {
    const double sA = partLength(in, H, in.anchor_height);
    const double sF = partLength(in, H, in.fairlead_height);
    return hangingPart(in, H, sA).x + hangingPart(in, H, sF).x +
           (L - sA - sF) * (1.0 + H / in.axial_stiffness) - in.horizontal_span;
  };
  // The parts lengthen with H: the laid part vanishes at H_max.
  const double H_min = 1e-9 * w * L;
  double H_max = w * L;
  while (laid(H_max) > 0.0) H_max *= 2.0;
  H_max = findRoot([&](double H) { return -laid(H); }, H_min, H_max);
  if (!(span(H_min) < 0.0 && span(H_max) > 0.0))
    throw std::runtime_error("the line does not lie on the bed between two hanging parts");
  LaidBetweenSolution out;
  out.horizontal_force = findRoot(span, H_min, H_max);
  out.anchor_part = partLength(in, out.horizontal_force, in.anchor_height);
  out.fairlead_part = partLength(in, out.horizontal_force, in.fairlead_height);
  out.laid_length = L - out.anchor_part - out.fairlead_part;
  out.weight = w;
  return out;
}

}  // namespace flexmoor::test
