// A measured elevation record as the sea (libhydro/waves/measured_sea.hpp): the components its
// FFT gives back reproduce the record, less its mean, at every sample to round-off, at a gauge
// off the origin and for an odd count too; the sea repeats every n dt; a cutoff keeps the
// components below it; and the FFT record of the components (elevation_record.hpp) is the input.
#include "libhydro/waves/measured_sea.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "libhydro/waves/elevation_record.hpp"
#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665, kDepth = 80.0;
const double kPi = std::acos(-1.0);

// A record with a mean offset of 0.12 m, three waves off the FFT grid and white noise.
ElevationRecord syntheticRecord(int n, double dt, double start) {
  ElevationRecord r{start, dt, std::vector<double>(n)};
  std::mt19937_64 engine(3);
  for (int j = 0; j < n; ++j) {
    const double t = start + j * dt;
    const double noise = static_cast<double>(engine() >> 11) * 0x1.0p-53 - 0.5;
    r.elevation[j] = 0.12 + 1.3 * std::cos(0.61 * t + 0.2) + 0.4 * std::sin(1.07 * t) +
                     0.2 * std::cos(2.3 * t - 1.0) + 0.05 * noise;
  }
  return r;
}

// Reference: the record itself. At its samples the reconstructed Sea's elevation is the record less
// its mean to 2e-13 of its largest |eta| (measured 5.5e-14: n / 2 cosines of round-off each ~1e-16,
// phases up to omega t ~ 1e3 rad), for n even (1,000) and odd (999), t0 = 12.5 s, at the origin and
// at a gauge 35 m along and 10 m across the heading 20 deg; the mean is given back apart (1e-14).
TEST(MeasuredSea, ComponentsReproduceTheRecordAtItsSamples) {
  for (const int n : {1000, 999}) {
    const ElevationRecord r = syntheticRecord(n, 0.4, 12.5);
    double largest = 0.0, mean = 0.0;
    for (double e : r.elevation) {
      largest = std::max(largest, std::abs(e));
      mean += e / n;
    }
    for (const Eigen::Vector2d& gauge : {Eigen::Vector2d(0, 0), Eigen::Vector2d(29.5, 21.4)}) {
      const double heading = 20.0 * kPi / 180.0;
      const ReconstructedSea s =
          reconstruct(r, heading, gauge, std::numeric_limits<double>::infinity(), kDepth, kG);
      EXPECT_NEAR(s.mean, mean, 1e-14);
      EXPECT_DOUBLE_EQ(s.repeat_period, n * 0.4);
      EXPECT_EQ(s.components.size(), static_cast<size_t>(n / 2));
      Sea sea(Water{1025.0, kDepth, kG});
      for (const WaveComponent& c : s.components) sea.addComponent(c);
      const Eigen::Vector3d x(gauge.x(), gauge.y(), 0.0);
      double worst = 0.0;
      for (int j = 0; j < n; ++j)
        worst = std::max(worst,
                         std::abs(sea.elevation(x, r.start + j * r.dt) - (r.elevation[j] - mean)));
      EXPECT_LT(worst, 2e-13 * largest) << n << " at " << gauge.transpose();
      // One period later the same (the sea repeats every n dt), to 1e-11.
      EXPECT_NEAR(sea.elevation(x, r.start + 17 * r.dt + s.repeat_period), r.elevation[17] - mean,
                  1e-11 * largest);
    }
  }
}

// The inverse FFT of the reconstruction at the record's own times (t0 = 0, its period, n
// samples) is the record less its mean to 1e-13 of its largest |eta| (an FFT round trip).
TEST(MeasuredSea, FftRecordOfTheComponentsIsTheInput) {
  const ElevationRecord r = syntheticRecord(512, 0.5, 0.0);
  const ReconstructedSea s = reconstruct(r, 0.0, Eigen::Vector2d::Zero(),
                                         std::numeric_limits<double>::infinity(), kDepth, kG);
  const std::vector<double> eta =
      elevationRecord(s.components, s.repeat_period, Eigen::Vector2d::Zero(), 1024);
  double largest = 0.0;
  for (double e : r.elevation) largest = std::max(largest, std::abs(e));
  // 1024 samples over the period: every other one is a sample of the record.
  for (int j = 0; j < 512; ++j)
    EXPECT_NEAR(eta[2 * j], r.elevation[j] - s.mean, 1e-13 * largest) << j;
}

// A cutoff at 0.2 Hz keeps the components with f <= 0.2 Hz only: k = 1 .. floor(0.2 n dt).
TEST(MeasuredSea, CutoffKeepsTheLowerFrequencies) {
  const ElevationRecord r = syntheticRecord(1000, 0.4, 0.0);
  const ReconstructedSea s =
      reconstruct(r, 0.0, Eigen::Vector2d::Zero(), 2.0 * kPi * 0.2, kDepth, kG);
  EXPECT_EQ(s.components.size(), 80u);  // 0.2 Hz x 400 s
  for (const WaveComponent& c : s.components) EXPECT_LE(c.omega, 2.0 * kPi * 0.2 * (1 + 1e-15));
}

}  // namespace
}  // namespace flexmoor::hydro
