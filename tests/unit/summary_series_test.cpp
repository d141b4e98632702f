// SeriesReduction: a value at a time and the max, min, mean and standard deviation over a window
// of a series given point by point, against closed forms.
#include "apps/output/summary_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace flexmoor::app {
namespace {

using R = SummarySpec::Reduction;

SummarySpec spec(R reduction, double from = -INFINITY, double to = INFINITY) {
  SummarySpec s;
  s.name = "q";
  s.reduction = reduction;
  s.from = from;
  s.to = to;
  return s;
}

SummarySpec atTime(double t) {
  SummarySpec s = spec(R::AtTime);
  s.at = t;
  return s;
}

// q = A cos(w t) sampled at t_k = k dt, k = 0..n.
double reduce(const SummarySpec& s, double A, double w, double dt, int n) {
  SeriesReduction r(s);
  for (int k = 0; k <= n; ++k) r.add(k * dt, A * std::cos(w * k * dt));
  return r.value();
}

const double kA = 2.5, kW = 2.0 * M_PI, kDt = 1.0 / 40;  // 40 steps a period of 1 s

// Between two points the value is their chord; at a point, the point (reference: the linear
// interpolation written out; tolerance 1e-15, round-off of one interpolation).
TEST(SeriesReduction, ValueAtATimeIsTheChordOfTheStepsAroundIt) {
  const double t = 1.01, t0 = 40 * kDt, t1 = 41 * kDt;
  const double q0 = kA * std::cos(kW * t0), q1 = kA * std::cos(kW * t1);
  EXPECT_NEAR(reduce(atTime(t), kA, kW, kDt, 160), q0 + (q1 - q0) * (t - t0) / kDt, 1e-15);
  EXPECT_NEAR(reduce(atTime(t1), kA, kW, kDt, 160), q1, 1e-15);
  EXPECT_EQ(reduce(atTime(0.0), kA, kW, kDt, 160), kA);           // the first point
  EXPECT_NEAR(reduce(atTime(4.0), kA, kW, kDt, 160), kA, 1e-14);  // the last
}

// Over whole periods at a constant step the trapezoidal rule is exact for cos and cos^2
// (40 > 2 points a period), so mean = 0 and std = A / sqrt(2) to round-off (tolerance 1e-14 A
// for 160 terms of size A dt); max and min are +-A, at sampled peaks and troughs (t = 0, 0.5 s).
TEST(SeriesReduction, StatisticsOfACosineOverWholePeriodsAreItsClosedForms) {
  EXPECT_EQ(reduce(spec(R::Max), kA, kW, kDt, 160), kA);
  EXPECT_NEAR(reduce(spec(R::Min), kA, kW, kDt, 160), -kA, 1e-15);
  EXPECT_NEAR(reduce(spec(R::Mean), kA, kW, kDt, 160), 0.0, 1e-14 * kA);
  EXPECT_NEAR(reduce(spec(R::Std), kA, kW, kDt, 160), kA / std::sqrt(2.0), 1e-14 * kA);
}

// A window whose edges fall between points, [1.0125, 3.0125] s (two whole periods): the series
// inside it plus the chords at the edges. Reference: mean 0 and std A / sqrt(2) of the cosine.
// Only the two half-step edge intervals differ from the whole-period sums, by the chord's error
// there, (w dt)^2 / 8 = 3.1e-3 A at most over dt / 2 of T = 2 s: a bound of 2e-5 A. Measured:
// mean 0 (the edges are symmetric about a trough), std -1.7e-7 A; tolerance 1e-6 A. Max: A at
// t = 2 s, a point inside.
TEST(SeriesReduction, AWindowBetweenStepsInterpolatesAtItsEdges) {
  const double a = 1.0125, b = 3.0125;
  EXPECT_NEAR(reduce(spec(R::Mean, a, b), kA, kW, kDt, 160), 0.0, 1e-6 * kA);
  EXPECT_NEAR(reduce(spec(R::Std, a, b), kA, kW, kDt, 160), kA / std::sqrt(2.0), 1e-6 * kA);
  EXPECT_NEAR(reduce(spec(R::Max, a, b), kA, kW, kDt, 160), kA, 1e-14);
}

// Over a window that holds no peak, max and min are the chords at its edges: cos falls over
// [0.11, 0.19] s (edges between points), so max is the chord at 0.11 s and min that at 0.19 s
// (reference: the chords written out; tolerance 1e-15, one interpolation's round-off).
TEST(SeriesReduction, MaxAndMinCountTheInterpolatedEdges) {
  const auto chord = [](double t) {
    const int k = static_cast<int>(std::floor(t / kDt));
    const double q0 = kA * std::cos(kW * k * kDt), q1 = kA * std::cos(kW * (k + 1) * kDt);
    return q0 + (q1 - q0) * (t - k * kDt) / kDt;
  };
  EXPECT_NEAR(reduce(spec(R::Max, 0.11, 0.19), kA, kW, kDt, 160), chord(0.11), 1e-15);
  EXPECT_NEAR(reduce(spec(R::Min, 0.11, 0.19), kA, kW, kDt, 160), chord(0.19), 1e-15);
}

// The standard deviation of a constant is zero, not the square root of a negative round-off,
// even on a large offset (the sums are taken from the first value).
TEST(SeriesReduction, StdOfAConstantOnALargeOffsetIsZero) {
  SeriesReduction r(spec(R::Std));
  for (int k = 0; k <= 100; ++k) r.add(0.01 * k, 1.0e8 + 0.1);
  EXPECT_EQ(r.value(), 0.0);
}

// A series that never reaches the time or the window is a program error, not a number.
TEST(SeriesReduction, NoPointAtTheTimeOrInTheWindowThrows) {
  EXPECT_THROW(reduce(atTime(5.0), kA, kW, kDt, 160), std::logic_error);
  EXPECT_THROW(reduce(spec(R::Mean, 5.0, 6.0), kA, kW, kDt, 160), std::logic_error);
}

}  // namespace
}  // namespace flexmoor::app
