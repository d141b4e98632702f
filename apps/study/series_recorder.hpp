#pragma once
// The collected quantities of a study member at every accepted state of their dynamic step
// inside their windows (the states the case's summary statistics see, summary_series.hpp), for
// the member's series.nc.
#include <string>
#include <vector>

#include "apps/output/state_observer.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

class SeriesRecorder : public StateObserver {
 public:
  // `specs` of one step (readSeriesQuantity's), evaluated on c.model; `c` must outlive the
  // recorder.
  SeriesRecorder(const Case& c, std::vector<SummarySpec> specs);

  void accepted(int step, const model::State& s, const model::Assembler& assembler) override;

  const std::vector<SummarySpec>& specs() const { return specs_; }
  // The times at which some spec's window holds the state, in time order.
  const std::vector<double>& time() const { return time_; }
  // values()[k][j]: spec k at time()[j]; NaN outside the spec's own window.
  const std::vector<std::vector<double>>& values() const { return values_; }

 private:
  const Case& c_;
  std::vector<SummarySpec> specs_;
  int step_ = -1;
  std::vector<double> time_;
  std::vector<std::vector<double>> values_;
};

}  // namespace flexmoor::app
