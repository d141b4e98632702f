#pragma once
// A history sampled at times t_0 < t_1 < ... < t_{n-1} (a table, a file of time series), as the
// cubic spline through the samples with de Boor's not-a-knot ends (the third derivative
// continuous at t_1 and t_{n-2}; a cubic is reproduced exactly). Its value, rate and
// acceleration are the spline's own and its first and second derivatives, so the velocity and
// acceleration a prescribed motion gets from it are exactly those of the position it follows: the
// acceleration continuous and piecewise linear, the rate continuous. With spacing h, a smooth
// history f is met to about h^4 |f''''| / 384 in value, h^3 |f''''| / 125 in rate and
// h^2 |f''''| / 13 in acceleration (a sine: tests/unit/cubic_spline_function_test.cpp), up to
// about 20 times that in the first and last intervals (the not-a-knot ends). Outside [t_0, t_{n-1}] it holds its end value (rate and
// acceleration 0). Three samples give the parabola through them, two the straight line, one a
// constant.
#include <vector>

#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

class CubicSplineFunction final : public TimeFunction {
 public:
  // Throws std::invalid_argument unless the times increase strictly, one value each, n >= 1.
  CubicSplineFunction(std::vector<double> times, std::vector<double> values);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;

 private:
  int interval(double t) const;    // i with t_i <= t < t_{i+1}, -1 outside
  std::vector<double> t_, f_, m_;  // samples and the spline's second derivatives there
};

}  // namespace flexmoor::model
