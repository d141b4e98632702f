// CoupledMotion (libstruct/model/coupled_motion.hpp): a host's motion of one dof between the
// ends of its steps.
#include "libstruct/model/coupled_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace flexmoor::model {
namespace {

using Sample = CoupledMotion::Sample;

// Check CM1. Given the values, rates and accelerations of a quintic at both ends of a step, the
// interpolant is that quintic (reference: the polynomial; tolerance 1e-12 of its scale,
// round-off); at the step's end it is the host's values exactly (tolerance 0).
TEST(CoupledMotion, QuinticEndsGiveTheQuinticAndTheEndExactly) {
  const auto p = [](double t, int order) {
    // 1 + 2 t - t^2 + 0.5 t^3 - 0.3 t^4 + 0.07 t^5 and its derivatives
    const double c[6] = {1, 2, -1, 0.5, -0.3, 0.07};
    double sum = 0.0;
    for (int k = order; k < 6; ++k) {
      double f = 1.0;
      for (int j = 0; j < order; ++j) f *= k - j;
      sum += f * c[k] * std::pow(t, k - order);
    }
    return sum;
  };
  const double t0 = 0.3, t1 = 1.7;
  CoupledMotion m(Sample{t0, p(t0, 0), p(t0, 1), p(t0, 2), true});
  m.next(Sample{t1, p(t1, 0), p(t1, 1), p(t1, 2), true});
  for (double t = t0; t <= t1; t += 0.05) {
    EXPECT_NEAR(m.value(t), p(t, 0), 1e-12 * 10);
    EXPECT_NEAR(m.rate(t), p(t, 1), 1e-11 * 10);
    EXPECT_NEAR(m.acceleration(t), p(t, 2), 1e-10 * 10);
  }
  EXPECT_EQ(m.value(t1), p(t1, 0));
  EXPECT_EQ(m.rate(t1), p(t1, 1));
  EXPECT_EQ(m.acceleration(t1), p(t1, 2));
  EXPECT_EQ(m.value(t1 + 1.0), p(t1, 0));  // after the step: its end
}

// Check CM2. Without accelerations the interpolant is the cubic Hermite of values and rates: a
// cubic is reproduced (reference: the cubic; tolerance 1e-12), and its acceleration at the end
// is the cubic's; a sine sampled 0.1 s apart is within the cubic Hermite's error bound
// h^4 max|f''''| / 384 (reference: the sine).
TEST(CoupledMotion, WithoutAccelerationsItIsTheCubicHermite) {
  const auto c = [](double t) { return 2.0 - t + 0.5 * t * t - 0.25 * t * t * t; };
  const auto dc = [](double t) { return -1.0 + t - 0.75 * t * t; };
  const auto ddc = [](double t) { return 1.0 - 1.5 * t; };
  CoupledMotion m(Sample{1.0, c(1.0), dc(1.0)});
  m.next(Sample{2.5, c(2.5), dc(2.5)});
  for (double t = 1.0; t <= 2.5; t += 0.1) {
    EXPECT_NEAR(m.value(t), c(t), 1e-12);
    EXPECT_NEAR(m.rate(t), dc(t), 1e-12);
    EXPECT_NEAR(m.acceleration(t), ddc(t), 1e-11);
  }
  const double w = 2.0, h = 0.1;
  CoupledMotion s(Sample{0.0, std::sin(0.0), w});
  s.next(Sample{h, std::sin(w * h), w * std::cos(w * h)});
  const double bound = std::pow(h, 4) * std::pow(w, 4) / 384.0;
  for (double t = 0.0; t <= h; t += h / 10)
    EXPECT_LE(std::abs(s.value(t) - std::sin(w * t)), bound);
}

// Check CM3. A held motion is constant; a step follows from the end of the last one.
TEST(CoupledMotion, HeldIsConstantAndStepsFollowOnFromTheLastEnd) {
  CoupledMotion m(Sample{0.0, 3.0, 0.0});
  EXPECT_EQ(m.value(-1.0), 3.0);
  EXPECT_EQ(m.value(5.0), 3.0);
  EXPECT_EQ(m.acceleration(5.0), 0.0);
  m.next(Sample{1.0, 4.0, 1.0});
  m.next(Sample{2.0, 5.0, 1.0});
  EXPECT_EQ(m.start().t, 1.0);
  EXPECT_EQ(m.value(1.0), 4.0);
  EXPECT_NEAR(m.value(1.5), 4.5, 1e-15);  // value and rate of a straight line
}

}  // namespace
}  // namespace flexmoor::model
