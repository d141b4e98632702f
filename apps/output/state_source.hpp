#pragma once
// One accepted state of a dynamic step as a SummarySource (summary_quantities.hpp): what a
// quantity asks for is computed on the first request and kept for the other quantities of the
// same state (the support reactions, one element's result, or all of them).
#include <map>
#include <optional>
#include <vector>

#include "apps/output/summary_quantities.hpp"
#include "libstruct/model/assembler.hpp"

namespace flexmoor::app {

class StateSource : public SummarySource {
 public:
  // `assembler` and `s` must outlive the source.
  StateSource(const model::Assembler& assembler, const model::State& s)
      : assembler_(assembler), state_(s) {}
  const model::State& state() const override { return state_; }
  const model::NodalField& reactions() const override;
  const element::ElementResult& element(int e) const override;
  const std::vector<element::ElementResult>& elements() const override;
  const std::vector<double>& frequencies() const override { return no_frequencies_; }

 private:
  const model::Assembler& assembler_;
  const model::State& state_;
  mutable std::optional<model::NodalField> reactions_;
  mutable std::map<int, element::ElementResult> one_;
  mutable std::optional<std::vector<element::ElementResult>> all_;
  const std::vector<double> no_frequencies_;  // a dynamic step has no modes
};

}  // namespace flexmoor::app
