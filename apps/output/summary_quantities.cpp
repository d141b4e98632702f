#include "apps/output/summary_quantities.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "apps/output/membrane_resultants.hpp"

namespace flexmoor::app {
namespace {

void requireIndex(int index, int count, const SummarySpec& spec, const char* what) {
  if (index < 0 || index >= count)
    throw std::out_of_range("summary \"" + spec.name + "\": " + what + " " + std::to_string(index) +
                            " is out of range (0.." + std::to_string(count - 1) + ")");
}

void requireNodeComponent(const SummarySpec& spec, const model::Model& model) {
  requireIndex(spec.node, model.nodeCount(), spec, "node");
  requireIndex(spec.component, 3, spec, "component");
}

// The largest end tension: the force on an element's end point, from its nodal force balance
// (Assembler::elementResults). Not the integration points' strain-based tensions, which quadratic
// and cubic cables get badly wrong when EA / T is large (within each element the axial force
// oscillates about the true one, by up to three times it for Example 1's cable on 16 x L3), while
// the end forces stay right to round-off; the tension of a catenary is largest at an end anyway.
double maxTension(const SummarySpec& spec, const ResultFrame& frame) {
  if (frame.elements.empty())
    throw std::out_of_range("summary \"" + spec.name + "\": the model has no elements");
  double t = -std::numeric_limits<double>::infinity();
  for (const element::ElementResult& r : frame.elements)
    t = std::max({t, r.end_tension[0], r.end_tension[1]});
  return t;
}

std::pair<double, double> principalResultants(const SummarySpec& spec, const ResultFrame& frame) {
  requireIndex(spec.element, static_cast<int>(frame.elements.size()), spec, "element");
  const auto resultants = app::principalResultants(frame.elements[spec.element]);
  if (!resultants)
    throw std::out_of_range("summary \"" + spec.name + "\": element " +
                            std::to_string(spec.element + 1) + " is not a membrane");
  return *resultants;
}

double unscaled(const SummarySpec& spec, const model::Model& model, const ResultFrame& frame) {
  using Q = SummarySpec::Quantity;
  const int n = spec.node, k = spec.component;
  switch (spec.quantity) {
    case Q::Displacement:
      requireNodeComponent(spec, model);
      return frame.state->displacement(k, n);
    case Q::Position:
      requireNodeComponent(spec, model);
      return model.reference()(k, n) + frame.state->displacement(k, n);
    case Q::Reaction:
      requireNodeComponent(spec, model);
      return frame.reactions(k, n);
    case Q::ReactionMagnitude:
      requireIndex(n, model.nodeCount(), spec, "node");
      return frame.reactions.col(n).norm();
    case Q::EndTension:
      requireIndex(spec.element, static_cast<int>(frame.elements.size()), spec, "element");
      requireIndex(spec.end, 2, spec, "end");
      return frame.elements[spec.element].end_tension[spec.end];
    case Q::MaxTension:
      return maxTension(spec, frame);
    case Q::Frequency:
      requireIndex(spec.mode - 1, static_cast<int>(frame.frequencies.size()), spec,
                   "mode (0-based)");
      return frame.frequencies[spec.mode - 1];
    case Q::ResultantMax:
      return principalResultants(spec, frame).first;
    case Q::ResultantMin:
      return principalResultants(spec, frame).second;
  }
  throw std::logic_error("summary \"" + spec.name + "\": unknown quantity");
}

}  // namespace

double evaluateSummary(const SummarySpec& spec, const model::Model& model,
                       const ResultFrame& frame) {
  return spec.scale * unscaled(spec, model, frame);
}

}  // namespace flexmoor::app
