// Airy kinematics checked against the equations they must satisfy, not against their own
// formulas: incompressibility and irrotationality (central differences in space), the bed and
// the linearised free-surface conditions, the linearised momentum equation a = -grad(p) / rho - g
// e_z, and the acceleration as the time derivative of the velocity, at shallow, intermediate and
// deep water and three headings. Plus Wheeler stretching, constant extrapolation, the dry region,
// a wave-train front and currents.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libhydro/waves/dispersion.hpp"
#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665, kRho = 1025.0;
const double kPi = std::acos(-1.0);

class AiryFieldEquations : public ::testing::TestWithParam<std::tuple<double, double>> {
 protected:
  // An 8 s wave at the depth giving k h (or deep water), heading beta, of height 5% of the depth
  // (2 m in deep water) so that the column points below stay wet; linear theory evaluated as it
  // stands below z = 0 (constant extrapolation changes nothing there).
  void SetUp() override {
    const auto [kh, heading] = GetParam();
    const double omega = 2.0 * kPi / 8.0;
    depth_ = std::isinf(kh) ? kh : kh / waveNumberFor(kh, omega);
    sea_ = std::make_unique<Sea>(Water{kRho, depth_, kG});
    const double height = std::isinf(depth_) ? 2.0 : 0.05 * depth_;
    sea_->addComponent(WaveComponent::fromHeightAndPeriod(height, 8.0, heading, 0.3, depth_, kG));
    sea_->setSurfaceKinematics(SurfaceKinematics::ConstantAboveMean);
    const WaveComponent& c = sea_->components().front();
    k_ = c.k;
    velocity_scale_ = c.amplitude * c.omega;
    pressure_scale_ = kRho * kG * c.amplitude;
  }
  // k with k tanh(k h) = omega^2 / g for the given k h: k = omega^2 / (g tanh(kh)).
  static double waveNumberFor(double kh, double omega) {
    return omega * omega / (kG * std::tanh(kh));
  }
  double depth_ = 0.0, k_ = 0.0, velocity_scale_ = 0.0, pressure_scale_ = 0.0;
  std::unique_ptr<Sea> sea_;
};

// Points through the column below the mean level, away from the bed by a step.
std::vector<Eigen::Vector3d> columnPoints(double depth, double k) {
  const double reach = std::isinf(depth) ? 3.0 / k : depth;
  std::vector<Eigen::Vector3d> points;
  for (double s : {0.05, 0.3, 0.6, 0.9})
    points.emplace_back(3.7 + 11.0 * s, -2.1 + 5.0 * s, -s * reach);
  return points;
}

// div v = 0 and curl v = 0 by central differences of step 1e-4 / k (truncation ~1e-8 of the
// velocity scale times k); asserted to 1e-6 of k a omega.
TEST_P(AiryFieldEquations, VelocityIsDivergenceFreeAndIrrotational) {
  const double d = 1e-4 / k_, t = 1.3;
  for (const Eigen::Vector3d& x : columnPoints(depth_, k_)) {
    Eigen::Matrix3d grad;  // grad(i, j) = d v_i / d x_j
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = d * Eigen::Vector3d::Unit(j);
      grad.col(j) = (sea_->at(x + e, t).velocity - sea_->at(x - e, t).velocity) / (2.0 * d);
    }
    const double scale = k_ * velocity_scale_;
    EXPECT_NEAR(grad.trace(), 0.0, 1e-6 * scale) << x.transpose();
    EXPECT_NEAR((grad - grad.transpose()).norm(), 0.0, 1e-6 * scale) << x.transpose();
  }
}

// a = dv/dt (central difference in time, step 1e-5 T) and the linearised momentum equation
// a = -grad(p) / rho - g e_z with the total gauge pressure, each to 1e-6 of a omega^2.
TEST_P(AiryFieldEquations, AccelerationIsTheRateOfVelocityAndBalancesThePressureGradient) {
  const double t = 2.9, dt = 8e-5, d = 1e-4 / k_;
  const double omega = sea_->components().front().omega;
  for (const Eigen::Vector3d& x : columnPoints(depth_, k_)) {
    const FluidPoint p = sea_->at(x, t);
    const Eigen::Vector3d rate =
        (sea_->at(x, t + dt).velocity - sea_->at(x, t - dt).velocity) / (2.0 * dt);
    EXPECT_LT((p.acceleration - rate).norm(), 1e-6 * velocity_scale_ * omega) << x.transpose();
    Eigen::Vector3d grad_p;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = d * Eigen::Vector3d::Unit(j);
      grad_p(j) = (sea_->at(x + e, t).pressure - sea_->at(x - e, t).pressure) / (2.0 * d);
    }
    const Eigen::Vector3d momentum = -grad_p / kRho - kG * Eigen::Vector3d::UnitZ();
    EXPECT_LT((p.acceleration - momentum).norm(), 1e-6 * velocity_scale_ * omega) << x.transpose();
  }
}

// Linearised boundary conditions: w = 0 at the bed; w = d eta / dt and p = rho g eta at z = 0,
// checked at the times of a period when z = 0 is wet (eta > 0 above it).
TEST_P(AiryFieldEquations, BedAndFreeSurfaceConditionsHold) {
  const double dt = 1e-5;
  const Eigen::Vector3d x(5.0, -3.0, 0.0);
  int checked = 0;
  for (double t = 0.0; t < 8.0; t += 0.7) {
    if (!std::isinf(depth_)) {
      EXPECT_NEAR(sea_->at(Eigen::Vector3d(5.0, -3.0, -depth_), t).velocity.z(), 0.0,
                  1e-12 * velocity_scale_);
    }
    if (!(sea_->elevation(x, t) > 0.0)) continue;
    const double deta = (sea_->elevation(x, t + dt) - sea_->elevation(x, t - dt)) / (2.0 * dt);
    EXPECT_NEAR(sea_->at(x, t).velocity.z(), deta, 1e-8 * velocity_scale_);
    EXPECT_NEAR(sea_->at(x, t).pressure, kRho * kG * sea_->elevation(x, t),
                1e-12 * pressure_scale_);
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

INSTANTIATE_TEST_SUITE_P(
    DepthsAndHeadings, AiryFieldEquations,
    ::testing::Combine(::testing::Values(0.3, 1.0, 3.0, std::numeric_limits<double>::infinity()),
                       ::testing::Values(0.0, kPi / 6.0, 0.75 * kPi)));

// A 10 m, 10 s wave in 40 m of water, checked at a crest and a trough.
class SurfaceKinematicsTest : public ::testing::Test {
 protected:
  Sea seaWith(SurfaceKinematics k) const {
    Sea sea(Water{kRho, 40.0, kG});
    sea.addComponent(WaveComponent::fromHeightAndPeriod(10.0, 10.0, 0.0, 0.0, 40.0, kG));
    sea.setSurfaceKinematics(k);
    return sea;
  }
  Sea linear_ = seaWith(SurfaceKinematics::ConstantAboveMean);
  Sea wheeler_ = seaWith(SurfaceKinematics::Wheeler);
  const Eigen::Vector3d crest_{0.0, 0.0, 0.0};  // theta = 0 at x = 0, t = 0: eta = a = 5 m
};

// Wheeler maps [-h, eta] onto [-h, 0]: at the crest the kinematics are linear theory's at z = 0,
// at the bed they are unchanged, and the total pressure vanishes at the surface.
TEST_F(SurfaceKinematicsTest, WheelerStretchesTheColumnToTheSurface) {
  const double eta = wheeler_.elevation(crest_, 0.0);
  ASSERT_NEAR(eta, 5.0, 1e-12);
  const FluidPoint top = wheeler_.at({0.0, 0.0, eta}, 0.0);
  EXPECT_TRUE(top.wet);
  EXPECT_LT((top.velocity - linear_.at({0.0, 0.0, 0.0}, 0.0).velocity).norm(), 1e-12);
  EXPECT_NEAR(top.pressure, 0.0, 1e-9 * kRho * kG * eta);
  const FluidPoint bed = wheeler_.at({0.0, 0.0, -40.0}, 0.0);
  EXPECT_LT((bed.velocity - linear_.at({0.0, 0.0, -40.0}, 0.0).velocity).norm(), 1e-12);
  // Half way down the stretched column is linear theory's half way down the still column.
  const FluidPoint mid = wheeler_.at({0.0, 0.0, 0.5 * (eta - 40.0)}, 0.0);
  EXPECT_LT((mid.velocity - linear_.at({0.0, 0.0, -20.0}, 0.0).velocity).norm(), 1e-12);
}

// Constant extrapolation holds z = 0's kinematics up to the crest; above the surface (and above
// a trough's surface, below z = 0) the point is dry and feels nothing.
TEST_F(SurfaceKinematicsTest, ConstantExtrapolationAndTheDryRegion) {
  const FluidPoint zero = linear_.at({0.0, 0.0, 0.0}, 0.0);
  const FluidPoint above = linear_.at({0.0, 0.0, 3.0}, 0.0);
  EXPECT_TRUE(above.wet);
  EXPECT_LT((above.velocity - zero.velocity).norm(), 1e-15);
  EXPECT_NEAR(above.pressure, kRho * kG * (5.0 - 3.0), 1e-9 * kRho * kG);  // p_dyn(0) - rho g z
  for (const Sea* sea : {&linear_, &wheeler_}) {
    const FluidPoint dry = sea->at({0.0, 0.0, 5.5}, 0.0);
    EXPECT_FALSE(dry.wet);
    EXPECT_EQ(dry.velocity.norm() + dry.acceleration.norm() + std::abs(dry.pressure), 0.0);
    const double trough_x = 0.5 * 2.0 * kPi / sea->components().front().k;
    EXPECT_FALSE(sea->at({trough_x, 0.0, -4.0}, 0.0).wet);  // eta = -5 m there
  }
}

// A wave train moving into still water: nothing ahead of the front, which moves at the group
// speed; the regular wave far behind it; the ramp's acceleration is still dv/dt (unstretched
// kinematics: Wheeler's z' moves with eta, which a local acceleration leaves out by design).
TEST(WaveFront, StillWaterAheadOfAFrontMovingAtTheGroupSpeed) {
  const double h = 20.0;
  Sea sea(Water{kRho, h, kG});
  sea.addComponent(WaveComponent::fromHeightAndPeriod(2.0, 5.0, 0.0, 0.0, h, kG));
  sea.setSurfaceKinematics(SurfaceKinematics::ConstantAboveMean);
  Sea regular = sea;
  sea.setFront({-6.0, WaveFront::Speed::Group, 2.0});
  const WaveComponent& c = sea.components().front();
  const double cg = groupSpeed(c.k, h, kG), t = 12.0, front = -6.0 + cg * t;
  const double ramp = 2.0 * 5.0 * cg;
  const Eigen::Vector3d ahead(front + 0.01, 0.0, -1.0), behind(front - ramp - 0.01, 0.0, -1.0);
  EXPECT_EQ(sea.at(ahead, t).velocity.norm(), 0.0);
  EXPECT_EQ(sea.elevation(ahead, t), 0.0);
  EXPECT_LT((sea.at(behind, t).velocity - regular.at(behind, t).velocity).norm(), 1e-15);
  const Eigen::Vector3d in_ramp(front - 0.4 * ramp, 0.0, -1.0);
  const double e = sea.elevation(in_ramp, t) / regular.elevation(in_ramp, t);
  EXPECT_NEAR(e, 0.4 * 0.4 * (3.0 - 2.0 * 0.4), 1e-12);  // 3 s^2 - 2 s^3 at s = 0.4
  const double dt = 1e-5;
  const Eigen::Vector3d rate =
      (sea.at(in_ramp, t + dt).velocity - sea.at(in_ramp, t - dt).velocity) / (2.0 * dt);
  EXPECT_LT((sea.at(in_ramp, t).acceleration - rate).norm(), 1e-7);
}

// Currents: uniform along a heading, a 1/7 power law (zero at the bed, U_s at the surface, held
// above it), and a table interpolated linearly and held beyond its ends.
TEST(Current, ProfilesAndHeading) {
  const CurrentProfile uniform = CurrentProfile::uniform(0.5, kPi / 2.0);
  EXPECT_LT((uniform.velocity(-10.0) - Eigen::Vector3d(0.0, 0.5, 0.0)).norm(), 1e-15);
  const CurrentProfile power = CurrentProfile::powerLaw(1.2, 7.0, 100.0, 0.0);
  EXPECT_EQ(power.speed(-100.0), 0.0);
  EXPECT_DOUBLE_EQ(power.speed(0.0), 1.2);
  EXPECT_DOUBLE_EQ(power.speed(2.0), 1.2);
  EXPECT_NEAR(power.speed(-50.0), 1.2 * std::pow(0.5, 1.0 / 7.0), 1e-15);
  const CurrentProfile table = CurrentProfile::table({{-50.0, 0.2}, {-10.0, 0.6}, {0.0, 1.0}}, 0.0);
  EXPECT_DOUBLE_EQ(table.speed(-30.0), 0.4);
  EXPECT_DOUBLE_EQ(table.speed(-80.0), 0.2);
  EXPECT_DOUBLE_EQ(table.speed(-5.0), 0.8);
  Sea sea(Water{kRho, 100.0, kG});
  sea.setCurrent(power);
  EXPECT_DOUBLE_EQ(sea.at({0.0, 0.0, -50.0}, 3.0).velocity.x(), power.speed(-50.0));
  EXPECT_EQ(sea.at({0.0, 0.0, -50.0}, 3.0).acceleration.norm(), 0.0);
}

}  // namespace
}  // namespace flexmoor::hydro
