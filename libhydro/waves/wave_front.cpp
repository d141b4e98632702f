#include "libhydro/waves/wave_front.hpp"

#include <cmath>

#include "libhydro/waves/dispersion.hpp"
#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

Envelope frontEnvelope(const WaveFront& front, const WaveComponent& c, double xi, double t,
                       double depth, double g) {
  const double speed = front.speed == WaveFront::Speed::Group ? groupSpeed(c.k, depth, g)
                                                              : phaseSpeed(c.k, depth, g);
  const double behind = front.start + speed * t - xi;  // distance behind the front
  if (behind <= 0.0) return {0.0, 0.0};
  const double ramp = front.ramp_periods * (2.0 * std::acos(-1.0) / c.omega) * speed;
  if (behind >= ramp) return {1.0, 0.0};
  const double s = behind / ramp;
  // d/dt of 3 s^2 - 2 s^3 with ds/dt = speed / ramp.
  return {s * s * (3.0 - 2.0 * s), 6.0 * s * (1.0 - s) * speed / ramp};
}

}  // namespace flexmoor::hydro
