#pragma once
// The value of a declared summary quantity, from the frame that closes its step or from one
// accepted state of a dynamic step (summary_series.hpp).
#include <vector>

#include "apps/output/result_frame.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

// What a quantity is read from: a state and, on demand, its support reactions, element results
// and natural frequencies. A frame holds them all; a time step's source computes only what a
// quantity asks for (one element's result for an end tension).
class SummarySource {
 public:
  virtual ~SummarySource() = default;
  virtual const model::State& state() const = 0;
  virtual const model::NodalField& reactions() const = 0;                   // 3 x nodes
  virtual const element::ElementResult& element(int e) const = 0;           // 0-based
  virtual const std::vector<element::ElementResult>& elements() const = 0;  // all of them
  virtual const std::vector<double>& frequencies() const = 0;               // rad/s; a modes step's
};

// Displacement, position (reference + displacement), velocity, speed |u'|, reaction component,
// reaction magnitude, horizontal reaction, length of a line on the seabed, end tension or the largest end tension over all elements, membrane
// resultants, mode frequency; times spec.scale. spec.reduction is not looked at: this is the
// value in one state of the case's model (a length on the seabed through the case's
// seabed_contact). Throws std::out_of_range when the spec names a node, element, end, component
// or mode the model or source does not have, or a length on the seabed without seabed contact.
double evaluateSummary(const SummarySpec& spec, const Case& c, const SummarySource& source);
double evaluateSummary(const SummarySpec& spec, const Case& c, const ResultFrame& frame);

}  // namespace flexmoor::app
