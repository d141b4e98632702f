#include "libhydro/waves/time_ramp.hpp"

#include <cmath>

namespace flexmoor::hydro {

Envelope rampEnvelope(const TimeRamp& ramp, double t) {
  const double s = (t - ramp.start) / ramp.duration;
  if (s <= 0.0) return {0.0, 0.0, 0.0, 0.0};
  if (s >= 1.0) return {};
  const double pi = std::acos(-1.0);
  return {0.5 * (1.0 - std::cos(pi * s)), 0.5 * pi / ramp.duration * std::sin(pi * s), 0.0, 0.0};
}

Envelope product(const Envelope& a, const Envelope& b) {
  return {a.value * b.value, a.rate * b.value + a.value * b.rate,
          a.slope * b.value + a.value * b.slope,
          a.rate_slope * b.value + a.rate * b.slope + a.slope * b.rate + a.value * b.rate_slope};
}

}  // namespace flexmoor::hydro
