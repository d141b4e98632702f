#include "libhydro/waves/measured_sea.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

#include "libhydro/signal/fft.hpp"
#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {

ReconstructedSea reconstruct(const ElevationRecord& record, double heading,
                             const Eigen::Vector2d& gauge, double omega_cutoff, double depth,
                             double g) {
  const int n = static_cast<int>(record.elevation.size());
  if (n < 2 || !(record.dt > 0.0))
    throw std::invalid_argument("reconstruct: needs 2 samples or more and dt > 0");
  const auto X = signal::forwardReal(record.elevation);
  ReconstructedSea sea;
  sea.repeat_period = n * record.dt;
  sea.mean = X[0].real() / n;
  const double two_pi = 2.0 * std::acos(-1.0);
  const double along = gauge.x() * std::cos(heading) + gauge.y() * std::sin(heading);
  for (int k = 1; k <= n / 2; ++k) {
    const double omega = two_pi * k / sea.repeat_period;
    if (omega > omega_cutoff) break;
    const double nyquist = 2 * k == n ? 0.5 : 1.0;
    WaveComponent c;
    c.amplitude = nyquist * 2.0 * std::abs(X[k]) / n;
    if (c.amplitude == 0.0) continue;
    c.omega = omega;
    c.k = waveNumber(omega, depth, g);
    c.heading = heading;
    c.phase = omega * record.start - std::arg(X[k]) - c.k * along;
    sea.components.push_back(c);
  }
  return sea;
}

}  // namespace flexmoor::hydro
