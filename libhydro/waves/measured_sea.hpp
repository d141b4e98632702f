#pragma once
// A measured elevation record eta(t_j) at one point, t_j = t0 + j dt (j = 0 .. n - 1), as the sea:
// its discrete Fourier transform X_k (FFTW, signal/fft.hpp) read as components
//   eta(t) = mean + sum_{k=1}^{n/2} a_k cos(omega_k (t - t0) + arg X_k),
//   omega_k = 2 pi k / (n dt),
//   a_k = 2 |X_k| / n (|X_{n/2}| / n for the Nyquist term of an even n),
// each a linear wave travelling along `heading` with k from the dispersion relation, phased so
// that at the gauge (x0, y0) the sum is the record: phi_k = omega_k t0 - arg X_k -
// k (x0 cos b + y0 sin b). At the samples the components give back the record less its mean to
// round-off; between them the trigonometric interpolation; the sea repeats every n dt. The mean
// (a still-water offset, not a wave) is returned apart and not part of the sea.
#include <Eigen/Core>
#include <vector>

#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

struct ElevationRecord {
  double start = 0.0;             // t0
  double dt = 0.0;                // sampling interval, > 0
  std::vector<double> elevation;  // n >= 2 samples
};

struct ReconstructedSea {
  std::vector<WaveComponent> components;  // k = 1 .. n/2 up to the cutoff, none of zero amplitude
  double mean = 0.0;                      // X_0 / n
  double repeat_period = 0.0;             // n dt
};

// The components with omega_k <= omega_cutoff (inf for all).
ReconstructedSea reconstruct(const ElevationRecord& record, double heading,
                             const Eigen::Vector2d& gauge, double omega_cutoff, double depth,
                             double g);

}  // namespace flexmoor::hydro
