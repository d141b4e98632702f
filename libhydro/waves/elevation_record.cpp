#include "libhydro/waves/elevation_record.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

#include "libhydro/signal/fft.hpp"

namespace flexmoor::hydro {

std::vector<double> elevationRecord(const std::vector<WaveComponent>& components,
                                    double repeat_period, const Eigen::Vector2d& at, int samples) {
  const double two_pi = 2.0 * std::acos(-1.0);
  if (!(repeat_period > 0.0) || samples < 2)
    throw std::invalid_argument("elevationRecord: needs a repeat period > 0 and 2 samples or more");
  std::vector<std::complex<double>> X(samples / 2 + 1, 0.0);
  for (const WaveComponent& c : components) {
    const double harmonic = c.omega * repeat_period / two_pi;
    const long m = std::lround(harmonic);
    if (std::abs(harmonic - m) > 1e-9 * std::max(1.0, harmonic) || m < 1)
      throw std::invalid_argument("elevationRecord: a component off the FFT grid of the period");
    if (2 * m >= samples)
      throw std::invalid_argument("elevationRecord: a component at or above the Nyquist frequency");
    const double psi =
        c.k * (at.x() * std::cos(c.heading) + at.y() * std::sin(c.heading)) + c.phase;
    X[m] += 0.5 * samples * c.amplitude * std::polar(1.0, -psi);
  }
  return signal::inverseReal(X, samples);
}

}  // namespace flexmoor::hydro
