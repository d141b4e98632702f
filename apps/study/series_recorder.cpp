#include "apps/study/series_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "apps/output/state_source.hpp"
#include "apps/output/summary_quantities.hpp"

namespace flexmoor::app {
namespace {

// A time this close to a window's bound is inside it (the run's time is a sum of steps).
bool within(double t, double from, double to) {
  const double slack = 1e-9 * std::max(1.0, std::abs(t));
  return t >= from - slack && t <= to + slack;
}

}  // namespace

SeriesRecorder::SeriesRecorder(const Case& c, std::vector<SummarySpec> specs)
    : c_(c), specs_(std::move(specs)), values_(specs_.size()) {
  if (!specs_.empty())
    step_ = specs_.front().step < 0 ? static_cast<int>(c.steps.size()) - 1 : specs_.front().step;
}

void SeriesRecorder::accepted(int step, const model::State& s, const model::Assembler& assembler) {
  if (step != step_) return;
  bool any = false;
  for (const SummarySpec& spec : specs_) any = any || within(s.time, spec.from, spec.to);
  if (!any) return;
  const StateSource source(assembler, s);
  time_.push_back(s.time);
  for (size_t k = 0; k < specs_.size(); ++k)
    values_[k].push_back(within(s.time, specs_[k].from, specs_[k].to)
                             ? evaluateSummary(specs_[k], c_, source)
                             : std::numeric_limits<double>::quiet_NaN());
}

}  // namespace flexmoor::app
