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
