// CubicSplineFunction (libstruct/model/cubic_spline_function.hpp): the not-a-knot cubic spline
// of a sampled history, against a cubic it must reproduce, the sine it was sampled from (the
// errors and their order in the spacing), its own finite differences, and a rigid platform's
// point moved by sampled motions.
#include "libstruct/model/cubic_spline_function.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::model {
namespace {

const double kPi = std::acos(-1.0);

CubicSplineFunction sampled(const TimeFunction& f, double from, double to, double h) {
  std::vector<double> t, v;
  for (int k = 0; from + k * h <= to + 1e-9 * h; ++k) {
    t.push_back(from + k * h);
    v.push_back(f.value(t.back()));
  }
  return CubicSplineFunction(t, v);
}

// A cubic through unevenly spaced samples is the not-a-knot spline itself: value, rate and
// acceleration to round-off (1e-13 absolute on values of order 1 to 10; measured 2.1e-15, a margin of 50).
TEST(CubicSplineFunction, ReproducesACubic) {
  const auto p = [](double t) { return 2.0 - 0.5 * t + 0.3 * t * t - 0.04 * t * t * t; };
  const auto dp = [](double t) { return -0.5 + 0.6 * t - 0.12 * t * t; };
  const auto ddp = [](double t) { return 0.6 - 0.24 * t; };
  const std::vector<double> t = {0.0, 0.7, 1.1, 2.5, 3.0, 4.6, 6.0};
  std::vector<double> v;
  for (double s : t) v.push_back(p(s));
  const CubicSplineFunction f(t, v);
  for (double s = 0.0; s <= 6.0; s += 0.13) {
    EXPECT_NEAR(f.value(s), p(s), 1e-13) << s;
    EXPECT_NEAR(f.rate(s), dp(s), 1e-13) << s;
    EXPECT_NEAR(f.acceleration(s), ddp(s), 1e-13) << s;
  }
}

// A table sampled from A sin(w t + 0.3), A = 2 m, w = 2 pi / 10 s, every h over 60 s
// reproduces the sine (997 times sampled). Inside (5 s from the ends) the errors are the
// interpolant's, value below h^4 w^4 A / 300, rate below h^3 w^4 A / 100, acceleration below
// h^2 w^4 A / 10 (measured coefficients 1/385, 1/125, 1/13 at every h from 1 s to 0.125 s), and
// each halving of h divides them by 2^4, 2^3, 2^2 (measured 16.2 to 16.6, 8.1 to 8.2, 3.8 to 4.3;
// held within [14, 18], [7, 9], [3.5, 4.5]); over the whole table, not-a-knot ends included,
// below h^4 w^4 A / 40, h^3 w^4 A / 5, h^2 w^4 A 0.6 (measured 1/44, 1/7, 1/1.9 at h = 1 s, less
// at finer h). At h = 0.25 s: 1.4e-5 m, 3.8e-4 m/s, 5.8e-3 m/s^2 at most.
TEST(CubicSplineFunction, TableOfASineReproducesTheSine) {
  const SineFunction sine(0.0, 2.0, 10.0, 0.3);
  const double w = 2.0 * kPi / 10.0, scale = std::pow(w, 4) * 2.0;
  double previous[3] = {0.0, 0.0, 0.0};
  for (const double h : {1.0, 0.5, 0.25, 0.125}) {
    const CubicSplineFunction f = sampled(sine, 0.0, 60.0, h);
    double all[3] = {0.0, 0.0, 0.0}, inside[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k <= 996; ++k) {
      const double t = 60.0 * k / 996.0;
      const double e[3] = {std::abs(f.value(t) - sine.value(t)), std::abs(f.rate(t) - sine.rate(t)),
                           std::abs(f.acceleration(t) - sine.acceleration(t))};
      for (int n = 0; n < 3; ++n) {
        all[n] = std::max(all[n], e[n]);
        if (t > 5.0 && t < 55.0) inside[n] = std::max(inside[n], e[n]);
      }
    }
    EXPECT_LT(inside[0], std::pow(h, 4) * scale / 300.0) << "h = " << h;
    EXPECT_LT(inside[1], std::pow(h, 3) * scale / 100.0) << "h = " << h;
    EXPECT_LT(inside[2], std::pow(h, 2) * scale / 10.0) << "h = " << h;
    EXPECT_LT(all[0], std::pow(h, 4) * scale / 40.0) << "h = " << h;
    EXPECT_LT(all[1], std::pow(h, 3) * scale / 5.0) << "h = " << h;
    EXPECT_LT(all[2], std::pow(h, 2) * scale * 0.6) << "h = " << h;
    if (previous[0] > 0.0) {
      EXPECT_GT(previous[0] / inside[0], 14.0) << "h = " << h;
      EXPECT_LT(previous[0] / inside[0], 18.0) << "h = " << h;
      EXPECT_GT(previous[1] / inside[1], 7.0) << "h = " << h;
      EXPECT_LT(previous[1] / inside[1], 9.0) << "h = " << h;
      EXPECT_GT(previous[2] / inside[2], 3.5) << "h = " << h;
      EXPECT_LT(previous[2] / inside[2], 4.5) << "h = " << h;
    }
    std::copy(inside, inside + 3, previous);
  }
}

// The rate is the derivative of the value and the acceleration that of the rate: central
// differences, step 1e-4 s (error h^2 / 6 |f'''| below 1e-8), held to 1e-7: the rate at knots
// too (t = 0.7, 9.8, 14 s), the acceleration inside intervals (at a knot the third derivative
// jumps, and the central difference of the rate averages its two sides).
TEST(CubicSplineFunction, DerivativesMatchFiniteDifferences) {
  const SineFunction sine(0.5, 1.5, 7.0, -0.4);
  const CubicSplineFunction f = sampled(sine, 0.0, 30.0, 0.7);
  const double d = 1e-4;
  for (double t : {0.05, 0.7, 3.33, 9.8, 14.0, 29.9})
    EXPECT_NEAR(f.rate(t), (f.value(t + d) - f.value(t - d)) / (2 * d), 1e-7) << t;
  for (double t : {0.05, 0.93, 3.33, 10.2, 14.3, 29.85})
    EXPECT_NEAR(f.acceleration(t), (f.rate(t + d) - f.rate(t - d)) / (2 * d), 1e-7) << t;
}

// Few samples: three give their parabola, two their line, one a constant; outside the table the
// end value holds with rate and acceleration 0. Exact forms to round-off (1e-14).
TEST(CubicSplineFunction, FewSamplesAndOutside) {
  const CubicSplineFunction parabola({0.0, 1.0, 3.0}, {1.0, 2.0, 10.0});  // 1 + 0 t + t^2
  EXPECT_NEAR(parabola.value(2.0), 5.0, 1e-14);
  EXPECT_NEAR(parabola.rate(2.0), 4.0, 1e-14);
  EXPECT_NEAR(parabola.acceleration(0.5), 2.0, 1e-14);
  const CubicSplineFunction line({1.0, 3.0}, {0.0, 4.0});
  EXPECT_NEAR(line.value(2.5), 3.0, 1e-14);
  EXPECT_NEAR(line.rate(1.2), 2.0, 1e-14);
  EXPECT_EQ(line.acceleration(2.0), 0.0);
  EXPECT_EQ(line.value(0.0), 0.0);
  EXPECT_EQ(line.value(5.0), 4.0);
  EXPECT_EQ(line.rate(5.0), 0.0);
  const CubicSplineFunction constant({2.0}, {7.0});
  EXPECT_EQ(constant.value(-1.0), 7.0);
  EXPECT_EQ(constant.value(9.0), 7.0);
  EXPECT_EQ(constant.rate(2.0), 0.0);
  EXPECT_THROW(CubicSplineFunction({0.0, 1.0, 1.0}, {0.0, 1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(CubicSplineFunction({0.0, 1.0}, {0.0}), std::invalid_argument);
}

// A fairlead of a platform moving by sampled surge, heave, pitch and yaw (tables every 0.25 s of
// sines): its velocity is the derivative of its position (central differences, step 1e-4 s, to
// 1e-7 m/s), and its position is the sine-driven platform's within the value bound above for
// the slowest-converging motion (2e-4 m with the 40 m arm; measured 9.4e-6 m).
TEST(CubicSplineFunction, RigidPointMovedBySampledMotions) {
  const auto sine = [](double a, double period, double phase) {
    return std::make_shared<SineFunction>(0.0, a, period, phase);
  };
  std::array<std::shared_ptr<const TimeFunction>, 6> sines = {
      sine(2.0, 10.0, 0.0), nullptr, sine(0.5, 13.0, 1.1), nullptr, sine(0.1, 11.0, 2.0),
      sine(0.3, 17.0, -0.7)};
  std::array<std::shared_ptr<const TimeFunction>, 6> tables;
  for (int k = 0; k < 6; ++k)
    if (sines[k])
      tables[k] = std::make_shared<CubicSplineFunction>(sampled(*sines[k], 0.0, 40.0, 0.25));
  const Eigen::Vector3d arm(40.0, 0.0, -15.0);
  const double d = 1e-4;
  for (int c = 0; c < 3; ++c) {
    const RigidPointMotion table(tables, arm, c, 0.0), exact(sines, arm, c, 0.0);
    for (double t : {0.3, 5.55, 17.2, 31.9}) {
      EXPECT_NEAR(table.rate(t), (table.value(t + d) - table.value(t - d)) / (2 * d), 1e-7);
      EXPECT_NEAR(table.value(t), exact.value(t), 2e-4) << "component " << c << ", t = " << t;
    }
  }
}

}  // namespace
}  // namespace flexmoor::model
