// RampedFunction (libstruct/model/time_function.hpp): a prescribed motion brought in by the
// quintic smoothstep. References: the closed form s f at chosen times, and central differences
// of value and rate for rate and acceleration.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {
namespace {

// A surge of 3 m at 12 s ramped over 12 s: at rest at t = 0 (value, rate and acceleration all
// zero, where the bare sine starts at 1.57 m/s), the smoothstep's midpoint s(6) = 1/2 exactly,
// and the bare sine from the ramp's end on.
TEST(RampedFunction, StartsAtRestAndBecomesTheMotion) {
  const auto sine = std::make_shared<SineFunction>(0.0, 3.0, 12.0, 0.0);
  const RampedFunction ramped(sine, 0.0, 12.0);
  EXPECT_EQ(ramped.value(0.0), 0.0);
  EXPECT_EQ(ramped.rate(0.0), 0.0);
  EXPECT_EQ(ramped.acceleration(0.0), 0.0);
  EXPECT_GT(sine->rate(0.0), 1.5);
  EXPECT_NEAR(ramped.value(6.0), 0.5 * sine->value(6.0), 1e-15);
  EXPECT_NEAR(ramped.value(3.0), (10.0 / 64 - 15.0 / 256 + 6.0 / 1024) * sine->value(3.0),
              1e-15);  // x = 1/4
  for (const double t : {12.0, 13.7, 40.0}) {
    EXPECT_EQ(ramped.value(t), sine->value(t));
    EXPECT_EQ(ramped.rate(t), sine->rate(t));
    EXPECT_EQ(ramped.acceleration(t), sine->acceleration(t));
  }
  EXPECT_EQ(ramped.period(), 12.0);
}

// The rate and acceleration are the derivatives of the value and the rate: central differences
// with h = 1e-5 s agree to 1e-8 relative (their truncation error, h^2 f''' / 6, is about 1e-10).
TEST(RampedFunction, RateAndAccelerationAreTheDerivatives) {
  const auto sine = std::make_shared<SineFunction>(0.4, 2.0, 5.0, 0.7);
  const RampedFunction ramped(sine, 1.0, 7.0);
  const double h = 1e-5;
  for (const double t : {1.3, 2.9, 4.5, 6.2, 7.9}) {
    const double rate = (ramped.value(t + h) - ramped.value(t - h)) / (2 * h);
    const double acc = (ramped.rate(t + h) - ramped.rate(t - h)) / (2 * h);
    EXPECT_NEAR(ramped.rate(t), rate, 1e-8 * std::max(1.0, std::abs(rate))) << t;
    EXPECT_NEAR(ramped.acceleration(t), acc, 1e-8 * std::max(1.0, std::abs(acc))) << t;
  }
}

}  // namespace
}  // namespace flexmoor::model
