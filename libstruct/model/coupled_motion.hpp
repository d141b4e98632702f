#pragma once
// The motion of one dof that a host program gives step by step (a platform simulator driving its
// fairleads): its value, rate and, when the host knows it, acceleration at the end t1 of each of
// the host's steps. Over the step, from the end t0 of the step before, the motion is the Hermite
// interpolant of the two ends: quintic when both ends have accelerations, else cubic in the
// values and rates (its acceleration at t1 is then the cubic's). At t1 it is the host's values
// exactly; before t0 and after t1, the nearest end's. So a time integrator that samples it at
// the step's end sees what the host gave, and sub-steps inside see a smooth motion between.
#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

class CoupledMotion final : public TimeFunction {
 public:
  // The dof's state at one time; has_acceleration false: not known.
  struct Sample {
    double t = 0.0, value = 0.0, rate = 0.0, acceleration = 0.0;
    bool has_acceleration = false;
  };
  // At rest in `start` until the first step.
  explicit CoupledMotion(const Sample& start) { hold(start); }

  // The host's next step ends at end.t (after the current end): the current end becomes its start.
  void next(const Sample& end);
  // The step from `start` to `end` (a state restored).
  void between(Sample start, Sample end);  // by value: next() passes its own end
  // At rest in `s` (no step under way).
  void hold(const Sample& s) { between(s, s); }
  const Sample& start() const { return start_; }
  const Sample& end() const { return end_; }

  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;

 private:
  // p(s) = sum c_k s^k over s = (t - t0) / h in [0, 1] (c in value units).
  double polynomial(double s, int order) const;
  Sample start_, end_;
  double h_ = 0.0;
  double c_[6] = {0, 0, 0, 0, 0, 0};
};

}  // namespace flexmoor::model
