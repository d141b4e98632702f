// The FFTW wrappers (libhydro/signal/fft.hpp) against the DFT summed directly, and Welch's
// estimate (welch.hpp) against Parseval's theorem for sinusoids on the segment's grid.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "libhydro/signal/fft.hpp"
#include "libhydro/signal/welch.hpp"

namespace flexmoor::signal {
namespace {

const double kPi = std::acos(-1.0);

// Reference: X_k = sum_j x_j exp(-2 pi i j k / n) summed in long double, for an even (16) and an
// odd (15) length. Tolerance 1e-13 of sum |x_j| (round-off of O(log n) operations is ~1e-15).
TEST(Fft, ForwardAndInverseMatchTheDirectSum) {
  for (int n : {16, 15}) {
    std::vector<double> x(n);
    double scale = 0.0;
    for (int j = 0; j < n; ++j) {
      x[j] = std::sin(0.7 * j * j + 0.3) + 0.1 * j;
      scale += std::abs(x[j]);
    }
    const auto X = forwardReal(x);
    ASSERT_EQ(X.size(), static_cast<size_t>(n / 2 + 1));
    for (int k = 0; k <= n / 2; ++k) {
      std::complex<long double> sum = 0.0L;
      for (int j = 0; j < n; ++j)
        sum += static_cast<long double>(x[j]) *
               std::polar(1.0L, -2.0L * static_cast<long double>(kPi) * j * k / n);
      EXPECT_NEAR(X[k].real(), static_cast<double>(sum.real()), 1e-13 * scale) << n << " " << k;
      EXPECT_NEAR(X[k].imag(), static_cast<double>(sum.imag()), 1e-13 * scale) << n << " " << k;
    }
    const auto back = inverseReal(X, n);
    for (int j = 0; j < n; ++j) EXPECT_NEAR(back[j], x[j], 1e-14 * scale) << n << " " << j;
  }
}

// Two sinusoids at bins 40 and 97 of 512-sample segments (a 4,096-sample record, 15 segments):
// the Hann-windowed periodogram of a whole number m >= 3 of cycles per segment keeps its power
// (sum (w x)^2 / sum w^2 = a^2 / 2 exactly: w^2 has no harmonic beyond 4 cycles), so the
// estimate's m0 is the variance a1^2 / 2 + a2^2 / 2 to round-off (1e-14 relative; measured
// 4e-16), its peak is
// the larger sinusoid's frequency to the bin, and m1 / m0 the power-weighted mean frequency.
TEST(Welch, KeepsTheVarianceOfSinusoidsOnTheGrid) {
  const double dt = 0.25, a1 = 1.5, a2 = 0.5;
  const int n = 4096, segment = 512;
  const double w1 = 2.0 * kPi * 40 / (segment * dt), w2 = 2.0 * kPi * 97 / (segment * dt);
  std::vector<double> x(n);
  for (int j = 0; j < n; ++j) x[j] = a1 * std::cos(w1 * j * dt + 0.4) + a2 * std::sin(w2 * j * dt);
  const SpectralEstimate e = welch(x, dt, segment);
  EXPECT_EQ(e.segments, 15);
  const double variance = 0.5 * (a1 * a1 + a2 * a2);
  EXPECT_NEAR(e.moment(0) / variance, 1.0, 1e-14);
  EXPECT_NEAR(e.moment(1) / (0.5 * (a1 * a1 * w1 + a2 * a2 * w2)), 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(e.peakFrequency(3), w1);
}

}  // namespace
}  // namespace flexmoor::signal
