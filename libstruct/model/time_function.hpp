#pragma once
// Scalar functions of time that drive loads and prescribed motions in dynamic steps, with their
// first and second derivatives (a prescribed support needs its velocity and acceleration too).
#include <memory>
#include <vector>

namespace flexmoor::model {

class TimeFunction {
 public:
  virtual ~TimeFunction() = default;
  virtual double value(double t) const = 0;
  virtual double rate(double t) const = 0;          // d/dt
  virtual double acceleration(double t) const = 0;  // d2/dt2
  // The period of a periodic function (what a time step must resolve); 0 for one that is not.
  virtual double period() const { return 0.0; }
};

// offset + amplitude sin(2 pi t / period + phase)
class SineFunction final : public TimeFunction {
 public:
  SineFunction(double offset, double amplitude, double period, double phase);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;
  double period() const override;

 private:
  double offset_, amplitude_, omega_, phase_;
};

// 0 before t0, linear from 0 to 1 over [t0, t0 + duration], 1 after.
class RampFunction final : public TimeFunction {
 public:
  RampFunction(double start, double duration);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double) const override { return 0.0; }

 private:
  double start_, duration_;
};

// A motion brought in smoothly: s(t) f(t), where s rises from 0 at `start` to 1 at start +
// duration as the quintic smoothstep s = 10 x^3 - 15 x^4 + 6 x^5, x = (t - start) / duration,
// whose rate and acceleration vanish at both ends, so a prescribed motion that starts at full
// speed (a platform's sine surge) begins at rest instead of with a jump in velocity. The rate and
// acceleration follow by the product rule: (s f)' = s' f + s f', (s f)'' = s'' f + 2 s' f' + s f''.
class RampedFunction final : public TimeFunction {
 public:
  RampedFunction(std::shared_ptr<const TimeFunction> f, double start, double duration);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;
  double period() const override { return f_->period(); }

 private:
  // s and its first and second derivatives at t.
  struct Smoothstep {
    double s, ds, dds;
  };
  Smoothstep ramp(double t) const;
  std::shared_ptr<const TimeFunction> f_;
  double start_, duration_;
};

// Piecewise linear through (t_i, f_i), constant outside; the acceleration of a piecewise-linear
// history is zero almost everywhere and is reported as such.
class TableFunction final : public TimeFunction {
 public:
  TableFunction(std::vector<double> times, std::vector<double> values);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double) const override { return 0.0; }

 private:
  int segment(double t) const;
  std::vector<double> t_, f_;
};

}  // namespace flexmoor::model
