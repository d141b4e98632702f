// The statistics study.nc holds (apps/study/study_statistics.hpp) on a known series: a sine
// q = m + A sin(omega t) sampled 64 times a period over 3 whole periods. The trapezoidal rule is
// exact for a trigonometric polynomial over its period, so mean m and std A / sqrt(2) hold to
// round-off; the samples fall on the peaks, so max m + A, min m - A and amplitude A too.
// Tolerance 1e-12 (round-off of 192 terms of order 1, measured below 1e-14).
#include "apps/study/study_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);

struct Sine {
  std::vector<double> t, v;
};

Sine sampledSine(double mean, double amplitude, double period, int per_period, int periods) {
  Sine s;
  for (int j = 0; j <= per_period * periods; ++j) {
    s.t.push_back(period * j / per_period);
    s.v.push_back(mean + amplitude * std::sin(2.0 * kPi * j / per_period));
  }
  return s;
}

TEST(StudyStatistics, SineOverWholePeriodsGivesItsClosedForms) {
  const Sine s = sampledSine(3.0, 2.0, 5.0, 64, 3);
  const app::SeriesStatistics st = app::seriesStatistics(s.t, s.v);
  EXPECT_NEAR(st.mean, 3.0, 1e-12);
  EXPECT_NEAR(st.std, 2.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(st.max, 5.0, 1e-12);
  EXPECT_NEAR(st.min, 1.0, 1e-12);
  EXPECT_NEAR(st.amplitude, 2.0, 1e-12);
}

// The points outside a variable's window are NaN in series.nc and are left out; the first
// period of a ramp-up (values 100 there) does not count.
TEST(StudyStatistics, PointsOutsideTheWindowAreLeftOut) {
  Sine s = sampledSine(0.0, 1.0, 1.0, 64, 2);
  for (int j = 0; j < 64; ++j) s.v[j] = std::numeric_limits<double>::quiet_NaN();
  s.v[10] = std::numeric_limits<double>::quiet_NaN();  // no effect either: a gap is bridged
  const app::SeriesStatistics st = app::seriesStatistics(s.t, s.v);
  EXPECT_NEAR(st.max, 1.0, 1e-12);
  EXPECT_NEAR(st.mean, 0.0, 1e-12);
  EXPECT_THROW(app::seriesStatistics({0.0}, {1.0}), std::logic_error);
}

// Resampled at a constant dt by linear interpolation: a straight line is kept exactly (1e-12).
TEST(StudyStatistics, ResamplingKeepsALineAndTheMedianStepIsTheTypicalOne) {
  const std::vector<double> t = {0.0, 0.1, 0.25, 0.3, 0.4, 0.5};
  std::vector<double> v;
  for (double x : t) v.push_back(2.0 * x + 1.0);
  const std::vector<double> r = app::resampled(t, v, 0.05);
  ASSERT_EQ(r.size(), 11u);
  for (size_t j = 0; j < r.size(); ++j) EXPECT_NEAR(r[j], 2.0 * 0.05 * j + 1.0, 1e-12) << j;
  EXPECT_NEAR(app::medianStep(t, v), 0.1, 1e-12);
}

}  // namespace
}  // namespace flexmoor::test
