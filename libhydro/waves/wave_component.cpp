#include "libhydro/waves/wave_component.hpp"

#include <cmath>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {
namespace {

const double kTwoPi = 2.0 * std::acos(-1.0);

}  // namespace

WaveComponent WaveComponent::fromHeightAndPeriod(double height, double period, double heading,
                                                 double phase, double depth, double g) {
  WaveComponent c;
  c.amplitude = 0.5 * height;
  c.omega = kTwoPi / period;
  c.k = waveNumber(c.omega, depth, g);
  c.heading = heading;
  c.phase = phase;
  return c;
}

double WaveComponent::theta(const Eigen::Vector3d& x, double t) const {
  return k * (x.x() * std::cos(heading) + x.y() * std::sin(heading)) - omega * t + phase;
}

Eigen::Vector3d WaveComponent::direction() const {
  return {std::cos(heading), std::sin(heading), 0.0};
}

ComponentTerms ComponentTerms::of(const WaveComponent& c, double depth, double rho, double g) {
  ComponentTerms t;
  t.direction = c.direction();
  t.kx = c.k * t.direction.x();
  t.ky = c.k * t.direction.y();
  t.k = c.k;
  t.omega = c.omega;
  t.phase = c.phase;
  t.amplitude = c.amplitude;
  t.velocity = c.amplitude * c.omega;
  t.acceleration = t.velocity * c.omega;
  t.pressure = rho * g * c.amplitude;
  if (!std::isinf(depth) && c.k * depth <= 350.0) {
    t.bed = std::exp(-2.0 * c.k * depth);
    t.over_sinh = 1.0 / (1.0 - t.bed);
    t.over_cosh = 1.0 / (1.0 + t.bed);
  }
  return t;
}

}  // namespace flexmoor::hydro
