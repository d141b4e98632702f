// A long-crested sea without a front takes the shorter sums of long_crested_sums.hpp; checked
// against the general sums of component_sums.hpp on the same sea: the same JONSWAP components
// (heading 0.6 rad) plus one of zero amplitude along another heading, which adds exact zeros to
// every sum but sends the Sea down the general path. Under a ramp (half-way up at the time
// checked, so E' != 0), at 200 m and in deep water, with Wheeler stretching, at points from 5 cm
// below the bed (a line resting on it) and 200 m down (where the shorter half of the components
// is left out as unfelt, long_crested_sums.hpp) to above the mean level; every field and
// gradient of Sea::at, each relative to its scale (sum over the components of a w, a w^2,
// rho g a and, for the gradients, times k).
// Measured at most 3.8e-17 (round-off: the sums' order differs, so the two paths are not equal
// to the bit, which shows the long-crested one was taken); asserted to 2e-16 (5x).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/wave_synthesis.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665, kRho = 1025.0;

class LongCrestedSea : public ::testing::TestWithParam<double> {
 protected:
  void SetUp() override {
    const double depth = GetParam();
    SynthesisOptions o;
    o.components = 80;
    o.seed = 11;
    o.heading = 0.6;
    long_ = std::make_unique<Sea>(Water{kRho, depth, kG});
    general_ = std::make_unique<Sea>(Water{kRho, depth, kG});
    for (const WaveComponent& c :
         synthesise(WaveSpectrum::jonswap(6.0, 10.0, 3.3), o, depth, kG).components) {
      long_->addComponent(c);
      general_->addComponent(c);
      velocity_ += c.amplitude * c.omega;
      acceleration_ += c.amplitude * c.omega * c.omega;
      pressure_ += kRho * kG * c.amplitude;
      k_max_ = std::max(k_max_, c.k);
    }
    WaveComponent other = long_->components().front();
    other.amplitude = 0.0;
    other.heading = -1.0;
    general_->addComponent(other);
    for (Sea* s : {long_.get(), general_.get()}) s->setRamp({10.0, 20.0});
  }

  std::unique_ptr<Sea> long_, general_;
  double velocity_ = 0.0, acceleration_ = 0.0, pressure_ = 0.0, k_max_ = 0.0;
};

TEST_P(LongCrestedSea, SumsMatchTheGeneralOnes) {
  const double t = 20.0, depth = GetParam(), reach = std::isinf(depth) ? 200.0 : depth + 0.05;
  double worst = 0.0;
  int points = 0;
  for (double s : {0.0, 0.3, 0.7, 1.0}) {
    const Eigen::Vector3d column(-40.0 + 90.0 * s, 25.0 * s, 0.0);
    const double eta = long_->elevation(column, t);
    for (double z : {-reach, -0.5 * reach, -0.1 * reach, -0.01 * reach, -0.2, 0.5 * eta}) {
      const Eigen::Vector3d x(column.x(), column.y(), z);
      FluidGradient gl, gg;
      const FluidPoint a = long_->at(x, t, gl), b = general_->at(x, t, gg);
      ASSERT_EQ(a.wet, b.wet);
      const auto err = [&](double diff, double scale) { worst = std::max(worst, diff / scale); };
      err(std::abs(a.elevation - b.elevation), pressure_ / (kRho * kG));
      err((a.velocity - b.velocity).norm(), velocity_);
      err((a.acceleration - b.acceleration).norm(), acceleration_);
      err(std::abs(a.pressure - b.pressure), pressure_ + kRho * kG * reach);
      err((gl.velocity - gg.velocity).norm(), k_max_ * velocity_);
      err((gl.acceleration - gg.acceleration).norm(), k_max_ * acceleration_);
      err((gl.pressure - gg.pressure).norm(), k_max_ * pressure_ + kRho * kG);
      err((gl.elevation - gg.elevation).norm(), k_max_ * pressure_ / (kRho * kG));
      FluidPoint plain = long_->at(x, t);  // without the gradient: the same values
      err((plain.velocity - b.velocity).norm(), velocity_);
      err((plain.acceleration - b.acceleration).norm(), acceleration_);
      err(std::abs(plain.pressure - b.pressure), pressure_ + kRho * kG * reach);
      ++points;
    }
  }
  EXPECT_EQ(points, 24);
  EXPECT_LT(worst, 2e-16);
  EXPECT_GT(worst, 0.0);  // two paths, not one
}

INSTANTIATE_TEST_SUITE_P(Depths, LongCrestedSea,
                         ::testing::Values(200.0, std::numeric_limits<double>::infinity()));

}  // namespace
}  // namespace flexmoor::hydro
