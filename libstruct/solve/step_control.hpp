#pragma once
// The choice of the next time step from the local error of the last one (Zienkiewicz and Xie's
// estimate for Newmark's family: the error of a step of h is h^2 (beta - 1/6) (u''_n+1 - u''_n),
// third order in h). The error arrives measured against its tolerance (1: just acceptable); the
// next step is h (safety / error)^(1/3), within [1/4, 2] times h and [dt_min, dt_max], no larger
// after a step that needed many Newton iterations or was retried, and unchanged while the error
// asks for less than a quarter more or 15% less.
#include <algorithm>
#include <cmath>

namespace flexmoor::solve {

class StepControl {
 public:
  static constexpr double kSafety = 0.8;     // aims below the tolerance, so few steps are retried
  static constexpr double kMaxGrowth = 2.0;  // per step
  static constexpr double kMinShrink = 0.25;
  // The step keeps its length while the error asks for a change within these bounds: a step of
  // the same length as the last reuses the matrices the last one's accepting evaluation left
  // (TimeIntegrator's kept_), which a new length must assemble again.
  static constexpr double kHoldBelow = 1.25, kHoldAbove = 0.85;
  // Beyond this many Newton iterations a step is not grown: a larger one would cost more
  // iterations than it saves in steps.
  static constexpr int kIterationsToHold = 6;

  // Whether a step whose error is `error` (against its tolerance) is kept.
  static bool accepts(double error) { return error <= 1.0; }

  // The step to try after one of h with `error` that took `iterations` Newton iterations;
  // `retried` when that step came after a rejected or failed attempt.
  static double next(double h, double error, int iterations, bool retried) {
    double factor = error > 0.0 ? kSafety * std::cbrt(1.0 / error) : kMaxGrowth;
    factor = std::clamp(factor, kMinShrink, kMaxGrowth);
    if (factor > 1.0 && (retried || iterations > kIterationsToHold)) factor = 1.0;
    if (factor > kHoldAbove && factor < kHoldBelow) factor = 1.0;
    return factor * h;
  }
};

}  // namespace flexmoor::solve
