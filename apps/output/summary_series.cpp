#include "apps/output/summary_series.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "apps/output/state_source.hpp"
#include "apps/output/summary_quantities.hpp"
#include "libstruct/model/assembler.hpp"

namespace flexmoor::app {
namespace {

using Reduction = SummarySpec::Reduction;

// The round-off of the run's time, a sum of time steps: a time this close to the series' first
// or last point is taken as that point.
double timeSlack(double t) { return 1e-9 * std::max(1.0, std::abs(t)); }

double interpolate(double t0, double v0, double t1, double v1, double t) {
  return t1 > t0 ? v0 + (v1 - v0) * (t - t0) / (t1 - t0) : v1;
}

}  // namespace

SeriesReduction::SeriesReduction(const SummarySpec& spec)
    : name_(spec.name), reduction_(spec.reduction), at_(spec.at), from_(spec.from), to_(spec.to) {}

void SeriesReduction::add(double t, double value) {
  if (!started_) {
    started_ = true;
    if (reduction_ == Reduction::AtTime && std::abs(t - at_) <= timeSlack(t)) {
      found_ = true;
      at_value_ = value;
    } else if (reduction_ != Reduction::AtTime && t >= from_ && t <= to_) {
      point(value);
    }
  } else {
    segment(t_, v_, t, value);
  }
  t_ = t;
  v_ = value;
}

// A point of the window's series, for max and min; the first sets the sums' reference.
void SeriesReduction::point(double value) {
  if (!found_) {
    found_ = true;
    max_ = min_ = ref_ = value;
  }
  max_ = std::max(max_, value);
  min_ = std::min(min_, value);
}

// The series between two accepted steps: a straight line from (t0, v0) to (t1, v1).
void SeriesReduction::segment(double t0, double v0, double t1, double v1) {
  if (reduction_ == Reduction::AtTime) {
    if (!found_ && at_ >= t0 && at_ <= t1) {
      found_ = true;
      at_value_ = interpolate(t0, v0, t1, v1, at_);
    }
    return;
  }
  const double a = std::max(t0, from_), b = std::min(t1, to_);
  if (a > b) return;  // outside the window
  const double va = interpolate(t0, v0, t1, v1, a), vb = interpolate(t0, v0, t1, v1, b);
  point(va);
  point(vb);
  const double h = b - a, qa = va - ref_, qb = vb - ref_;
  length_ += h;
  sum_ += 0.5 * h * (qa + qb);                    // trapezoidal rule for the integral of q
  sum_squares_ += 0.5 * h * (qa * qa + qb * qb);  // and of q^2
}

void SeriesReduction::save(std::vector<double>& out) const {
  out.insert(out.end(), {started_ ? 1.0 : 0.0, found_ ? 1.0 : 0.0, t_, v_, at_value_, max_, min_,
                         ref_, length_, sum_, sum_squares_});
}

void SeriesReduction::resume(const double*& in) {
  started_ = in[0] != 0.0;
  found_ = in[1] != 0.0;
  t_ = in[2], v_ = in[3], at_value_ = in[4], max_ = in[5], min_ = in[6];
  ref_ = in[7], length_ = in[8], sum_ = in[9], sum_squares_ = in[10];
  in += 11;
}

bool SeriesReduction::reached() const {
  if (reduction_ == Reduction::AtTime)
    return found_ || (started_ && std::abs(t_ - at_) <= timeSlack(t_));
  return found_;
}

double SeriesReduction::value() const {
  if (reduction_ == Reduction::AtTime) {
    if (found_) return at_value_;
    if (started_ && std::abs(t_ - at_) <= timeSlack(t_)) return v_;  // the step's end
    throw std::logic_error("summary \"" + name_ +
                           "\": no time step at or around the time asked for");
  }
  if (!found_) throw std::logic_error("summary \"" + name_ + "\": no time step in the window");
  switch (reduction_) {
    case Reduction::Max:
      return max_;
    case Reduction::Min:
      return min_;
    case Reduction::Mean:
    case Reduction::Std: {
      if (length_ <= 0.0)
        throw std::logic_error("summary \"" + name_ + "\": the window has no length");
      const double mean = sum_ / length_;
      if (reduction_ == Reduction::Mean) return ref_ + mean;
      // Cauchy-Schwarz keeps the variance of a positive-weight rule >= 0 but for round-off.
      return std::sqrt(std::max(0.0, sum_squares_ / length_ - mean * mean));
    }
    case Reduction::StepEnd:
    case Reduction::AtTime:
      break;
  }
  throw std::logic_error("summary \"" + name_ + "\": not a reduction over time");
}

SummarySeries::SummarySeries(const Case& c, int step, const model::Assembler& assembler)
    : c_(c), assembler_(assembler) {
  const int last = static_cast<int>(c.steps.size()) - 1;
  for (size_t k = 0; k < c.summary.size(); ++k) {
    const SummarySpec& spec = c.summary[k];
    if (spec.reduction == Reduction::StepEnd || (spec.step < 0 ? last : spec.step) != step)
      continue;
    specs_.push_back(static_cast<int>(k));
    reductions_.emplace_back(spec);
  }
}

void SummarySeries::sample(const model::State& s) {
  if (specs_.empty()) return;
  const StateSource source(assembler_, s);
  for (size_t k = 0; k < specs_.size(); ++k)
    reductions_[k].add(s.time, evaluateSummary(c_.summary[specs_[k]], c_, source));
}

std::vector<double> SummarySeries::progress() const {
  std::vector<double> out;
  for (const SeriesReduction& r : reductions_) r.save(out);
  return out;
}

void SummarySeries::resume(const std::vector<double>& progress) {
  if (progress.size() != 11 * reductions_.size())
    throw std::invalid_argument("the summary's series in the checkpoint are not this case's");
  const double* in = progress.data();
  for (SeriesReduction& r : reductions_) r.resume(in);
}

std::vector<std::pair<int, double>> SummarySeries::values() const {
  std::vector<std::pair<int, double>> out;
  for (size_t k = 0; k < specs_.size(); ++k)
    if (reductions_[k].reached()) out.emplace_back(specs_[k], reductions_[k].value());
  return out;
}

}  // namespace flexmoor::app
