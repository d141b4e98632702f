#pragma once
// Summary quantities taken over the time series of a dynamic step (SummarySpec::Reduction):
// the value at a time, linearly interpolated between the two accepted time steps around it, or
// the maximum, minimum, mean or standard deviation over a window [a, b] of the step.
//
// Every accepted time step counts (sub-steps of a cut step included), not only the ones written
// to netCDF, so `output_every` does not change a value. Over the window the series is the
// accepted steps inside it plus the values interpolated linearly at a and b:
//   max, min  over those points;
//   mean      (1/T) integral of q dt, T = b - a, by the trapezoidal rule over those points;
//   std       the population standard deviation of q over time,
//             sqrt((1/T) integral of (q - mean)^2 dt), from the trapezoidal means of q and q^2.
// Sampled at a constant dt over whole periods, q = A cos(w t) gives mean 0 and std A / sqrt(2)
// to round-off (the trapezoidal rule is exact for a trigonometric polynomial over its period);
// max is A cos(w dt / 2) at worst, when no step falls on the peak. Otherwise the error is that
// of the linear interpolation between steps, O(dt^2). The statistic is of the scaled
// value (scale: -1 turns a max into minus the min).
#include <string>
#include <utility>
#include <vector>

#include "apps/problem/case.hpp"
#include "libstruct/model/assembler.hpp"

namespace flexmoor::app {

// One reduction of a time series given point by point in time order.
class SeriesReduction {
 public:
  // `at` for AtTime, the window [from, to] (infinite bounds: the whole series) for the others.
  explicit SeriesReduction(const SummarySpec& spec);

  void add(double t, double value);  // t not before the last one added
  // Throws std::logic_error when no point of the series was at `at` or in the window (the case
  // reader makes sure it is in the step).
  double value() const;
  // Whether the series reached its time or its window (a host's run may end before).
  bool reached() const;
  // What the series has gathered, as numbers (a checkpoint in a file), and back.
  void save(std::vector<double>& out) const;
  void resume(const double*& in);

 private:
  void point(double value);
  void segment(double t0, double v0, double t1, double v1);

  std::string name_;
  SummarySpec::Reduction reduction_;
  double at_, from_, to_;
  bool started_ = false, found_ = false;
  double t_ = 0.0, v_ = 0.0;  // the last point added
  double at_value_ = 0.0;     // AtTime
  double max_ = 0.0, min_ = 0.0;
  double ref_ = 0.0;  // the first value in the window; the sums are of q - ref_
  double length_ = 0.0, sum_ = 0.0, sum_squares_ = 0.0;  // T, integral of q - ref and its square
};

// The summary quantities of a case taken over one dynamic step, fed every accepted state.
// Each state computes only what the quantities ask for: nothing else for a node's position or
// velocity, one element's result for an end tension, the support reactions (one residual) for a
// reaction, every element's result only for max_tension.
class SummarySeries {
 public:
  // The specs of c.summary whose step is `step` (0-based) and whose reduction is not StepEnd.
  // `c` and `assembler` must outlive the series.
  SummarySeries(const Case& c, int step, const model::Assembler& assembler);

  bool empty() const { return specs_.empty(); }
  // Every accepted state of the step in time order, the step's first state (its start
  // acceleration known) first.
  void sample(const model::State& s);
  // What the reductions have gathered, as numbers, and back (a checkpoint in a file).
  std::vector<double> progress() const;
  // std::invalid_argument when `progress` is not of these specs.
  void resume(const std::vector<double>& progress);
  // After the step: (index in c.summary, value) of each of its specs whose time or window the
  // step reached (a host may end a step before a window it was not given the time to reach).
  std::vector<std::pair<int, double>> values() const;

 private:
  const Case& c_;
  const model::Assembler& assembler_;
  std::vector<int> specs_;  // indices into c.summary
  std::vector<SeriesReduction> reductions_;
};

}  // namespace flexmoor::app
