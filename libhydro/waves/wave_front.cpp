#include "libhydro/waves/wave_front.hpp"

#include <cmath>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {

ComponentFront componentFront(const WaveFront& front, const WaveComponent& c, double depth,
                              double g) {
  ComponentFront f;
  f.start = front.start;
  f.speed = front.speed == WaveFront::Speed::Group ? groupSpeed(c.k, depth, g)
                                                   : phaseSpeed(c.k, depth, g);
  f.ramp = front.ramp_periods * (2.0 * std::acos(-1.0) / c.omega) * f.speed;
  return f;
}

Envelope frontEnvelope(const ComponentFront& front, double xi, double t) {
  const double behind = front.start + front.speed * t - xi;  // distance behind the front
  if (behind <= 0.0) return {0.0, 0.0, 0.0, 0.0};
  if (behind >= front.ramp) return {};
  const double s = behind / front.ramp, c = front.speed / front.ramp;
  // E = 3 s^2 - 2 s^3 with ds/dt = c_front / ramp, ds/dxi = -1 / ramp.
  const double e_s = 6.0 * s * (1.0 - s), e_ss = 6.0 - 12.0 * s;
  return {s * s * (3.0 - 2.0 * s), e_s * c, -e_s / front.ramp, -e_ss * c / front.ramp};
}

}  // namespace flexmoor::hydro
