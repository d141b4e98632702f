#pragma once
// A ramp-up of the whole sea in time, for response-amplitude studies in regular waves (and for
// starting an irregular sea gently): every component's amplitude times
//   E(t) = 0 before t_s, (1 - cos(pi (t - t_s) / T_r)) / 2 over [t_s, t_s + T_r], 1 after,
// a half-cosine whose slope is zero at both ends, on the elevation, the velocity, the dynamic
// pressure and (with dE/dt times the velocity, so that it stays du/dt) the acceleration, at every
// point alike (a front, wave_front.hpp, ramps in space behind a moving front instead; the two
// multiply).
#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

struct TimeRamp {
  double start = 0.0;     // t_s
  double duration = 0.0;  // T_r > 0
};

// E(t) and dE/dt (no slope in space).
Envelope rampEnvelope(const TimeRamp& ramp, double t);

// The envelope of a product of two: value, rate, slope and the slope of the rate by the product
// rule.
Envelope product(const Envelope& a, const Envelope& b);

}  // namespace flexmoor::hydro
