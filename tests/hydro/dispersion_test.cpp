// The linear dispersion relation omega^2 = g k tanh(k h) (docs/theory.md) at any depth, its limits, and
// the group speed as d omega / d k.
#include "libhydro/waves/dispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665;
const double kInf = std::numeric_limits<double>::infinity();

double omegaOf(double k, double h) { return std::sqrt(kG * k * std::tanh(k * h)); }

// Residual |omega^2 / (g k tanh k h) - 1| below 1e-12 (the required bound; round-off is ~1e-16)
// from k h = 1e-5 (very shallow) to 200 (deep), 200 points a decade apart by 10^(1/20).
TEST(Dispersion, ResidualBelow1e12AtEveryDepth) {
  const double h = 50.0;
  double worst = 0.0;
  for (double kh = 1e-5; kh < 200.0; kh *= std::pow(10.0, 0.05)) {
    const double omega = omegaOf(kh / h, h);
    const double k = waveNumber(omega, h, kG);
    worst = std::max(worst, std::abs(omega * omega / (kG * k * std::tanh(k * h)) - 1.0));
    EXPECT_NEAR(k * h / kh, 1.0, 1e-12) << "kh " << kh;
  }
  EXPECT_LT(worst, 1e-12);
}

// Deep water: k = omega^2 / g exactly for h = inf, and to e^-2kh for k h = 20 (4e-18).
// Shallow water: tanh x = x - x^3 / 3 + ... gives k = k_s (1 + (k h)^2 / 6 + O((k h)^4)) with
// k_s = omega / sqrt(g h); at k h = 1e-4 the series holds to 1e-16, checked to 1e-13.
TEST(Dispersion, DeepAndShallowLimits) {
  const double omega = 2.0 * std::acos(-1.0) / 8.0;
  EXPECT_DOUBLE_EQ(waveNumber(omega, kInf, kG), omega * omega / kG);
  const double k_deep = omega * omega / kG;
  EXPECT_NEAR(waveNumber(omega, 20.0 / k_deep, kG) / k_deep, 1.0, 1e-15);
  const double h = 1.0, omega_shallow = 1e-4 * std::sqrt(kG * h);
  const double k_s = omega_shallow / std::sqrt(kG * h), kh = k_s * h;
  EXPECT_NEAR(waveNumber(omega_shallow, h, kG) / k_s - 1.0, kh * kh / 6.0, 1e-13);
}

// c_g = d omega / d k by central differences (relative 1e-8; the difference's own error is
// ~1e-10 at a step of 1e-5 k), and c_g -> c / 2 in deep water, -> c in shallow water.
TEST(Dispersion, GroupSpeedIsTheSlopeOfTheDispersionRelation) {
  const double h = 30.0;
  for (double kh : {0.05, 0.5, 1.0, 2.0, 5.0}) {
    const double k = kh / h, dk = 1e-5 * k;
    const double slope = (omegaOf(k + dk, h) - omegaOf(k - dk, h)) / (2.0 * dk);
    EXPECT_NEAR(groupSpeed(k, h, kG) / slope, 1.0, 1e-8) << "kh " << kh;
    EXPECT_NEAR(phaseSpeed(k, h, kG), omegaOf(k, h) / k, 1e-12 * omegaOf(k, h) / k);
  }
  const double k = 0.1;
  EXPECT_DOUBLE_EQ(groupSpeed(k, kInf, kG), 0.5 * phaseSpeed(k, kInf, kG));
  EXPECT_NEAR(groupSpeed(1e-4, 1.0, kG) / phaseSpeed(1e-4, 1.0, kG), 1.0, 1e-8);
}

}  // namespace
}  // namespace flexmoor::hydro
