// Sea's closed-form gradients (velocity, local acceleration, gauge pressure and elevation in
// position) checked against central differences of Sea::at itself: two components of different
// headings, a wave-train front whose ramp covers the points, a 1/7 power-law current (20 m) or a table (100 m), at
// intermediate, moderate and infinite depth, Wheeler stretching and constant extrapolation,
// points deep, near the mean level and between the mean level and the crest; and flowGradient
// above the surface (the flow of the surface point below), against central differences of
// flowBelowSurface.
//
// Reference step d = 1e-5 / k_max: truncation ~ (k d)^2 / 6 ~ 2e-11 of a gradient, round-off
// ~ 1e-16 |p| / d (the hydrostatic pressure, up to 1e6 Pa here, makes the pressure's the
// largest). Each error is taken relative to the gradient's scale (velocity k a omega,
// acceleration k a omega^2, pressure rho g (1 + k a), elevation k a, from the larger
// component).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libhydro/waves/flow_gradient.hpp"
#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665, kRho = 1025.0;

struct Errors {
  double velocity = 0.0, acceleration = 0.0, pressure = 0.0, elevation = 0.0;
};

class SeaGradient : public ::testing::TestWithParam<std::tuple<double, SurfaceKinematics>> {
 protected:
  void SetUp() override {
    const auto [depth, surface] = GetParam();
    depth_ = depth;
    sea_ = std::make_unique<Sea>(Water{kRho, depth, kG});
    sea_->addComponent(WaveComponent::fromHeightAndPeriod(2.0, 8.0, 0.0, 0.3, depth, kG));
    sea_->addComponent(WaveComponent::fromHeightAndPeriod(1.0, 5.0, 0.7, 1.1, depth, kG));
    sea_->setFront({-20.0, WaveFront::Speed::Group, 2.0});
    if (depth == 20.0) sea_->setCurrent(CurrentProfile::powerLaw(0.8, 7.0, depth, -0.3));
    if (depth == 100.0)
      sea_->setCurrent(CurrentProfile::table({{-100.0, 0.2}, {-50.0, 0.5}, {0.0, 0.9}}, 0.4));
    sea_->setSurfaceKinematics(surface);
    const WaveComponent& c = sea_->components().front();
    k_max_ = std::max(c.k, sea_->components().back().k);
    scale_ = {c.k * c.amplitude * c.omega, c.k * c.amplitude * c.omega * c.omega,
              kRho * kG * (1.0 + c.k * c.amplitude), c.k * c.amplitude};
  }

  // The largest error of the closed form against central differences at x, relative to scale_.
  Errors errorsAt(const Eigen::Vector3d& x, double t) const {
    FluidGradient g;
    const FluidPoint f = sea_->at(x, t, g);
    EXPECT_TRUE(f.wet);
    const double d = 1e-5 / k_max_;
    Errors e;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d plus = x, minus = x;
      plus(j) += d;
      minus(j) -= d;
      const FluidPoint a = sea_->at(plus, t), b = sea_->at(minus, t);
      const auto err = [&](double& out, double diff, double scale) {
        out = std::max(out, std::abs(diff) / scale);
      };
      err(e.velocity, ((a.velocity - b.velocity) / (2 * d) - g.velocity.col(j)).norm(),
          scale_.velocity);
      err(e.acceleration,
          ((a.acceleration - b.acceleration) / (2 * d) - g.acceleration.col(j)).norm(),
          scale_.acceleration);
      err(e.pressure, (a.pressure - b.pressure) / (2 * d) - g.pressure(j), scale_.pressure);
      err(e.elevation, (a.elevation - b.elevation) / (2 * d) - g.elevation(j), scale_.elevation);
    }
    return e;
  }

  // Points inside the first component's ramp at time t = 6 s (the front at -20 m + c_g t, the
  // points 12-38 m behind it, the ramp 2 T c_g = 100-110 m long), at depths from near the bed to
  // the mean level, and (where the crest is above it) halfway between the mean level and the
  // crest.
  std::vector<Eigen::Vector3d> points(double t) const {
    const double reach = std::isinf(depth_) ? 30.0 : 0.9 * depth_;
    std::vector<Eigen::Vector3d> out;
    for (double s : {0.1, 0.4, 0.7}) {
      Eigen::Vector3d x(-20.0 + 6.0 * t * s, 3.0 * s, 0.0);
      for (double depth : {-reach, -0.4 * reach, -0.05}) out.emplace_back(x.x(), x.y(), depth);
      const double eta = sea_->elevation(x, t);
      if (eta > 0.05) out.emplace_back(x.x(), x.y(), 0.5 * eta);
    }
    return out;
  }

  double depth_ = 0.0, k_max_ = 0.0;
  Errors scale_;
  std::unique_ptr<Sea> sea_;
};

// Measured at most 2.3e-10 (the velocity at 20 m, the power law's shear 2 m above the bed: the
// reference's truncation) and 9.1e-11 for the rest; asserted to 1e-9 (4x the largest). With the
// shear by central differences of step 1e-4 h instead, the velocity's error was 1.4e-6.
TEST_P(SeaGradient, ClosedFormMatchesCentralDifferences) {
  const double t = 6.0;
  Errors worst;
  for (const Eigen::Vector3d& x : points(t)) {
    const Errors e = errorsAt(x, t);
    worst.velocity = std::max(worst.velocity, e.velocity);
    worst.acceleration = std::max(worst.acceleration, e.acceleration);
    worst.pressure = std::max(worst.pressure, e.pressure);
    worst.elevation = std::max(worst.elevation, e.elevation);
  }
  EXPECT_LT(worst.velocity, 1e-9);
  EXPECT_LT(worst.acceleration, 1e-9);
  EXPECT_LT(worst.pressure, 1e-9);
  EXPECT_LT(worst.elevation, 1e-9);
}

// Above the surface the flow is that of (x, y, eta(x, y)): its gradient has no z column and
// the chain rule through grad eta in x and y. Reference as above; measured at most 8.8e-11,
// asserted to 1e-9.
TEST_P(SeaGradient, AboveTheSurfaceFollowsTheSurfacePoint) {
  const double t = 6.0, d = 1e-5 / k_max_;
  double worst_v = 0.0, worst_a = 0.0;
  for (const Eigen::Vector3d& below : points(t)) {
    const Eigen::Vector3d x(below.x(), below.y(), sea_->elevation(below, t) + 0.5);
    const FlowGradient g = flowGradient(*sea_, x, t);
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d plus = x, minus = x;
      plus(j) += d;
      minus(j) -= d;
      const FlowKinematics a = flowBelowSurface(*sea_, plus, t);
      const FlowKinematics b = flowBelowSurface(*sea_, minus, t);
      worst_v = std::max(worst_v, ((a.velocity - b.velocity) / (2 * d) - g.velocity.col(j)).norm() /
                                      scale_.velocity);
      worst_a = std::max(
          worst_a, ((a.acceleration - b.acceleration) / (2 * d) - g.acceleration.col(j)).norm() /
                       scale_.acceleration);
    }
  }
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_a, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    DepthsAndSurfaceKinematics, SeaGradient,
    ::testing::Combine(::testing::Values(20.0, 100.0, std::numeric_limits<double>::infinity()),
                       ::testing::Values(SurfaceKinematics::Wheeler,
                                         SurfaceKinematics::ConstantAboveMean)));

}  // namespace
}  // namespace flexmoor::hydro
