#include "apps/case/read/read_time_span.hpp"

#include <cmath>

#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

// One segment {dt, steps} of a time schedule.
std::optional<solve::TimeSegment> readSegment(CaseBuilder& b, Fields& f) {
  const YAML::Node* dt = f.require("dt");
  const YAML::Node* steps = f.require("steps");
  const auto h = dt ? b.in.quantity(*dt, f.path("dt"), kind::kTime, Limit::Positive) : std::nullopt;
  const auto count = steps ? b.in.integer(*steps, f.path("steps"), 1) : std::nullopt;
  if (!h || !count) return std::nullopt;
  return solve::TimeSegment{*h, *count};
}

void readSchedule(CaseBuilder& b, Fields& f, const YAML::Node& list,
                  std::vector<solve::TimeSegment>& schedule) {
  const std::vector<YAML::Node> items = listItems(b.diag, list, f.path("schedule"));
  if (items.empty() && (list.IsNull() || list.IsSequence()))
    b.diag.error(list, f.path("schedule") + ": no segments (expected at least one {dt, steps})");
  for (size_t i = 0; i < items.size(); ++i) {
    Fields segment(b.diag, items[i], itemPath(f.path("schedule"), i), {"dt", "steps"});
    if (const auto s = readSegment(b, segment)) schedule.push_back(*s);
  }
}

// The whole number of steps dt that make `span` (within round-off), or an error at `n`.
std::optional<int> wholeSteps(CaseBuilder& b, const YAML::Node& n, const std::string& what,
                              double span, double dt) {
  const double ratio = span / dt;
  const double steps = std::round(ratio);
  if (steps >= 1.0 && std::abs(ratio - steps) <= 1e-9 * ratio && steps < 2e9)
    return static_cast<int>(steps);
  b.diag.error(n, what + ": not a whole number of time steps (got " + formatNumber(ratio) +
                      " steps of dt, expected a multiple of dt = " + formatNumber(dt) + ")");
  return std::nullopt;
}

// A key that only one way of stepping takes, given with the other.
void notWith(CaseBuilder& b, const Fields& f, const std::vector<std::string>& keys,
             const std::string& expected) {
  for (const std::string& key : keys)
    if (const YAML::Node* n = f.find(key))
      b.diag.error(*n, f.path(key) + ": not a key of this step's time (" + expected + ")");
}

void readAdaptive(CaseBuilder& b, Fields& f, double duration, StepSpec& step) {
  solve::AdaptiveSteps a;
  a.duration = duration;
  a.tolerance = b.in.quantityOr(f, "step_tolerance", kind::kNumber, Limit::Positive, a.tolerance);
  a.dt_max = b.in.quantityOr(f, "dt_max", kind::kTime, Limit::Positive, 0.0);
  a.dt_min = b.in.quantityOr(f, "dt_min", kind::kTime, Limit::Positive, 0.0);
  if (a.dt_min > 0.0 && a.dt_max > 0.0 && a.dt_min > a.dt_max)
    b.diag.error(*f.find("dt_min"), f.path("dt_min") + ": above dt_max (got " +
                                        formatNumber(a.dt_min) + ", expected at most " +
                                        formatNumber(a.dt_max) + ")");
  step.output_interval = duration / 1000.0;
  if (const YAML::Node* n = f.find("output")) {
    const auto interval = b.in.quantity(*n, f.path("output"), kind::kTime, Limit::Positive);
    if (interval && *interval > duration)
      b.diag.error(*n, f.path("output") + ": longer than the step (got " + formatNumber(*interval) +
                           ", expected at most the duration " + formatNumber(duration) + ")");
    else if (interval)
      step.output_interval = *interval;
  }
  notWith(b, f, {"output_every"}, "expected output: an interval, with steps chosen by accuracy");
  step.dynamic.adaptive = a;
}

}  // namespace

const std::vector<std::string>& timeSpanKeys() {
  static const std::vector<std::string> keys = {"schedule",       "dt",     "steps",
                                                "duration",       "output", "output_every",
                                                "step_tolerance", "dt_max", "dt_min"};
  return keys;
}

void readTimeSpan(CaseBuilder& b, Fields& f, StepSpec& step) {
  std::vector<solve::TimeSegment>& schedule = step.dynamic.schedule;
  const YAML::Node* list = f.find("schedule");
  const YAML::Node* dt = f.find("dt");
  const YAML::Node* steps = f.find("steps");
  const YAML::Node* duration = f.find("duration");
  if (list && (dt || steps || duration)) {
    b.diag.error(*list, f.path("schedule") + ": given with " +
                            (dt      ? "dt"
                             : steps ? "steps"
                                     : "duration") +
                            " (expected either schedule: [{dt, steps}, ...], dt with steps or "
                            "duration, or duration alone for steps chosen by their accuracy)");
    return;
  }
  if (!list && !dt && !steps && !duration) {
    if (f.isMap())
      b.diag.error(f.node(), f.path() +
                                 ": missing key 'duration' (expected duration: T for steps "
                                 "chosen by their accuracy, dt with steps or duration, or "
                                 "schedule: [{dt, steps}, ...])");
    return;
  }
  if (duration && !dt && !steps) {
    const auto T = b.in.quantity(*duration, f.path("duration"), kind::kTime, Limit::Positive);
    if (T) readAdaptive(b, f, *T, step);
    return;
  }
  notWith(b, f, {"step_tolerance", "dt_max", "dt_min"},
          "expected without dt: they bound the steps chosen by accuracy");
  if (list) {
    readSchedule(b, f, *list, schedule);
  } else if (duration && steps) {
    b.diag.error(*duration, f.path("duration") +
                                ": given with steps (expected dt with one of steps or duration)");
    return;
  } else if (duration) {
    const auto h = b.in.quantity(*dt, f.path("dt"), kind::kTime, Limit::Positive);
    const auto T = b.in.quantity(*duration, f.path("duration"), kind::kTime, Limit::Positive);
    if (!h || !T) return;
    if (const auto n = wholeSteps(b, *duration, f.path("duration"), *T, *h))
      schedule.push_back({*h, *n});
  } else if (const auto segment = readSegment(b, f)) {
    schedule.push_back(*segment);
  }
  if (const YAML::Node* n = f.find("output")) {
    if (f.find("output_every")) {
      b.diag.error(*n, f.path("output") + ": given with output_every (expected one of the two)");
      return;
    }
    const auto interval = b.in.quantity(*n, f.path("output"), kind::kTime, Limit::Positive);
    if (!interval || schedule.empty()) return;
    if (schedule.size() > 1) {
      b.diag.error(*n, f.path("output") +
                           ": with a schedule of several dt (expected output_every: N steps)");
      return;
    }
    if (const auto every = wholeSteps(b, *n, f.path("output"), *interval, schedule[0].dt))
      step.output_every = *every;
    return;
  }
  step.output_every = b.in.integerOr(f, "output_every", 1, step.output_every);
}

}  // namespace flexmoor::app
