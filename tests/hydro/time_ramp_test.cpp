// The ramp-up in time (libhydro/waves/time_ramp.hpp) on a Sea: still water before its start,
// the half-cosine E(t) = (1 - cos(pi s)) / 2 on the elevation, the very same sea after it (to
// the bit), the local acceleration du/dt of the ramped velocity (against central differences in
// time), and the product with a front's envelope.
#include "libhydro/waves/time_ramp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665;
const double kPi = std::acos(-1.0);

Sea regularSea(double depth) {
  Sea sea(Water{1025.0, depth, kG});
  sea.addComponent(WaveComponent::fromHeightAndPeriod(2.0, 8.0, 0.3, 0.4, depth, kG));
  sea.addComponent(WaveComponent::fromHeightAndPeriod(0.6, 5.0, -0.5, 1.2, depth, kG));
  // Linear theory at the point itself (below the mean level): Wheeler's stretching would move
  // the point's z' with eta(t), which Sea's local acceleration (linear theory's du/dt at z') leaves
  // out on purpose, with or without a ramp.
  sea.setSurfaceKinematics(SurfaceKinematics::ConstantAboveMean);
  return sea;
}

// E and dE/dt: 0 before t_s, (1 - cos(pi s)) / 2 and pi / (2 T_r) sin(pi s) on the ramp (exact
// values at s = 1/2: 1/2 and pi / (2 T_r)), 1 and 0 after; the slopes in space zero.
TEST(TimeRamp, IsAHalfCosineInTime) {
  const TimeRamp ramp{5.0, 20.0};
  const Envelope before = rampEnvelope(ramp, 4.0), mid = rampEnvelope(ramp, 15.0),
                 after = rampEnvelope(ramp, 25.0);
  EXPECT_EQ(before.value, 0.0);
  EXPECT_EQ(before.rate, 0.0);
  EXPECT_NEAR(mid.value, 0.5, 1e-15);
  EXPECT_NEAR(mid.rate, kPi / 40.0, 1e-15);
  EXPECT_EQ(mid.slope, 0.0);
  EXPECT_EQ(after.value, 1.0);
  EXPECT_EQ(after.rate, 0.0);
  const Envelope q = rampEnvelope(ramp, 10.0);  // s = 1/4
  EXPECT_NEAR(q.value, 0.5 * (1.0 - std::cos(kPi / 4.0)), 1e-15);
}

// The ramped sea: elevation and kinematics zero (wet points at the mean level's water) before the
// start; during the ramp eta is E(t) times the unramped eta (1e-15 relative), and the acceleration
// is the time derivative of the velocity by central differences in t (h = 1e-4 s: truncation ~
// (omega h)^2 / 6 ~ 1e-9, round-off 1e-16 / h ~ 1e-12, of a omega^2; tolerance 1e-8 of it, measured
// 1.4e-9); after it every field equals the unramped sea's to the bit (E = 1, dE/dt = 0 exactly).
TEST(TimeRamp, RampsTheSeaAndKeepsAccelerationTheRateOfVelocity) {
  for (const double depth : {30.0, std::numeric_limits<double>::infinity()}) {
    Sea plain = regularSea(depth), ramped = regularSea(depth);
    ramped.setRamp({2.0, 24.0});
    const Eigen::Vector3d x(3.0, -2.0, -4.0);
    const FluidPoint still = ramped.at(x, 1.0);
    EXPECT_EQ(still.elevation, 0.0);
    EXPECT_EQ(still.velocity.norm(), 0.0);
    EXPECT_EQ(still.acceleration.norm(), 0.0);
    const WaveComponent& c = plain.components().front();
    const double a_scale = c.amplitude * c.omega * c.omega, h = 1e-4;
    for (const double t : {3.0, 9.5, 17.2, 25.9}) {
      const double e = rampEnvelope({2.0, 24.0}, t).value;
      EXPECT_NEAR(ramped.elevation(x, t), e * plain.elevation(x, t), 1e-15 * c.amplitude);
      const Eigen::Vector3d dv =
          (ramped.at(x, t + h).velocity - ramped.at(x, t - h).velocity) / (2 * h);
      EXPECT_LT((ramped.at(x, t).acceleration - dv).norm(), 1e-8 * a_scale) << depth << " " << t;
    }
    for (const double t : {26.0, 40.0}) {
      FluidGradient gp, gr;
      const FluidPoint p = plain.at(x, t, gp), r = ramped.at(x, t, gr);
      EXPECT_EQ(p.elevation, r.elevation);
      EXPECT_EQ(p.velocity, r.velocity);
      EXPECT_EQ(p.acceleration, r.acceleration);
      EXPECT_EQ(p.pressure, r.pressure);
      EXPECT_EQ(gp.velocity, gr.velocity);
      EXPECT_EQ(gp.acceleration, gr.acceleration);
    }
  }
}

// A ramp and a front multiply: the product rule on given envelopes (exact to round-off), and on a
// sea inside both ramps the acceleration the time derivative of the velocity (central
// differences as above, 1e-8 of a omega^2), so the product's rate is right.
TEST(TimeRamp, MultipliesAFrontsEnvelope) {
  const Envelope f{0.3, 0.05, -0.02, 0.004}, r{0.6, 0.1, 0.0, 0.0};
  const Envelope p = product(f, r);
  EXPECT_DOUBLE_EQ(p.value, 0.18);
  EXPECT_DOUBLE_EQ(p.rate, 0.05 * 0.6 + 0.3 * 0.1);
  EXPECT_DOUBLE_EQ(p.slope, -0.02 * 0.6);
  EXPECT_DOUBLE_EQ(p.rate_slope, 0.004 * 0.6 + -0.02 * 0.1);
  // On a sea: the front at the group speed from x = -40 m, a 2-period ramp; the time ramp 30 s.
  Sea sea = regularSea(50.0);
  sea.setFront({-40.0, WaveFront::Speed::Group, 2.0});
  sea.setRamp({0.0, 30.0});
  const Eigen::Vector3d x(0.0, 0.0, -3.0);
  const double h = 1e-4;
  for (const double t : {14.0, 20.0}) {
    const Eigen::Vector3d dv = (sea.at(x, t + h).velocity - sea.at(x, t - h).velocity) / (2 * h);
    const WaveComponent& c = sea.components().front();
    EXPECT_LT((sea.at(x, t).acceleration - dv).norm(), 1e-8 * c.amplitude * c.omega * c.omega) << t;
  }
}

}  // namespace
}  // namespace flexmoor::hydro
