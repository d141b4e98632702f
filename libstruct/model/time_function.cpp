#include "libstruct/model/time_function.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexmoor::model {

SineFunction::SineFunction(double offset, double amplitude, double period, double phase)
    : offset_(offset),
      amplitude_(amplitude),
      omega_(2.0 * std::acos(-1.0) / period),
      phase_(phase) {}

double SineFunction::value(double t) const {
  return offset_ + amplitude_ * std::sin(omega_ * t + phase_);
}
double SineFunction::rate(double t) const {
  return amplitude_ * omega_ * std::cos(omega_ * t + phase_);
}
double SineFunction::acceleration(double t) const {
  return -amplitude_ * omega_ * omega_ * std::sin(omega_ * t + phase_);
}
double SineFunction::period() const { return 2.0 * std::acos(-1.0) / omega_; }

RampFunction::RampFunction(double start, double duration) : start_(start), duration_(duration) {
  if (!(duration > 0.0)) throw std::invalid_argument("a ramp needs a positive duration");
}
double RampFunction::value(double t) const {
  return std::clamp((t - start_) / duration_, 0.0, 1.0);
}
double RampFunction::rate(double t) const {
  return (t > start_ && t < start_ + duration_) ? 1.0 / duration_ : 0.0;
}

RampedFunction::RampedFunction(std::shared_ptr<const TimeFunction> f, double start, double duration)
    : f_(std::move(f)), start_(start), duration_(duration) {
  if (!f_) throw std::invalid_argument("a ramp needs a function to ramp");
  if (!(duration > 0.0)) throw std::invalid_argument("a ramp needs a positive duration");
}
RampedFunction::Smoothstep RampedFunction::ramp(double t) const {
  const double x = (t - start_) / duration_;
  if (x <= 0.0) return {0.0, 0.0, 0.0};
  if (x >= 1.0) return {1.0, 0.0, 0.0};
  const double x2 = x * x;
  return {x2 * x * (10.0 - 15.0 * x + 6.0 * x2), 30.0 * x2 * (1.0 - x) * (1.0 - x) / duration_,
          60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration_ * duration_)};
}
double RampedFunction::value(double t) const { return ramp(t).s * f_->value(t); }
double RampedFunction::rate(double t) const {
  const Smoothstep r = ramp(t);
  return r.ds * f_->value(t) + r.s * f_->rate(t);
}
double RampedFunction::acceleration(double t) const {
  const Smoothstep r = ramp(t);
  return r.dds * f_->value(t) + 2.0 * r.ds * f_->rate(t) + r.s * f_->acceleration(t);
}

TableFunction::TableFunction(std::vector<double> times, std::vector<double> values)
    : t_(std::move(times)), f_(std::move(values)) {
  if (t_.empty() || t_.size() != f_.size())
    throw std::invalid_argument("a table needs as many values as times, at least one");
  if (!std::is_sorted(t_.begin(), t_.end()) || std::adjacent_find(t_.begin(), t_.end()) != t_.end())
    throw std::invalid_argument("table times must increase strictly");
}
int TableFunction::segment(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return static_cast<int>(it - t_.begin()) - 1;  // -1 before the table
}
double TableFunction::value(double t) const {
  const int i = segment(t);
  if (i < 0) return f_.front();
  if (i >= static_cast<int>(t_.size()) - 1) return f_.back();
  const double s = (t - t_[i]) / (t_[i + 1] - t_[i]);
  return f_[i] + s * (f_[i + 1] - f_[i]);
}
double TableFunction::rate(double t) const {
  const int i = segment(t);
  if (i < 0 || i >= static_cast<int>(t_.size()) - 1) return 0.0;
  return (f_[i + 1] - f_[i]) / (t_[i + 1] - t_[i]);
}

}  // namespace flexmoor::model
