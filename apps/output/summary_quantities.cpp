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
double maxTension(const SummarySpec& spec, const model::Model& model, const SummarySource& source) {
  if (model.elementCount() == 0)
    throw std::out_of_range("summary \"" + spec.name + "\": the model has no elements");
  double t = -std::numeric_limits<double>::infinity();
  for (const element::ElementResult& r : source.elements())
    t = std::max({t, r.end_tension[0], r.end_tension[1]});
  return t;
}

const element::ElementResult& elementResult(const SummarySpec& spec, const model::Model& model,
                                            const SummarySource& source) {
  requireIndex(spec.element, model.elementCount(), spec, "element");
  return source.element(spec.element);
}

std::pair<double, double> principalResultants(const SummarySpec& spec, const model::Model& model,
                                              const SummarySource& source) {
  const auto resultants = app::principalResultants(elementResult(spec, model, source));
  if (!resultants)
    throw std::out_of_range("summary \"" + spec.name + "\": element " +
                            std::to_string(spec.element + 1) + " is not a membrane");
  return *resultants;
}

// The frame closing a step: everything is already computed.
class FrameSource : public SummarySource {
 public:
  explicit FrameSource(const ResultFrame& frame) : frame_(frame) {}
  const model::State& state() const override { return *frame_.state; }
  const model::NodalField& reactions() const override { return frame_.reactions; }
  const element::ElementResult& element(int e) const override { return frame_.elements.at(e); }
  const std::vector<element::ElementResult>& elements() const override { return frame_.elements; }
  const std::vector<double>& frequencies() const override { return frame_.frequencies; }

 private:
  const ResultFrame& frame_;
};

double unscaled(const SummarySpec& spec, const model::Model& model, const SummarySource& source) {
  using Q = SummarySpec::Quantity;
  const int n = spec.node, k = spec.component;
  switch (spec.quantity) {
    case Q::Displacement:
      requireNodeComponent(spec, model);
      return source.state().displacement(k, n);
    case Q::Position:
      requireNodeComponent(spec, model);
      return model.reference()(k, n) + source.state().displacement(k, n);
    case Q::Velocity:
      requireNodeComponent(spec, model);
      return source.state().velocity(k, n);
    case Q::Speed:
      requireIndex(n, model.nodeCount(), spec, "node");
      return source.state().velocity.col(n).norm();
    case Q::Reaction:
      requireNodeComponent(spec, model);
      return source.reactions()(k, n);
    case Q::ReactionMagnitude:
      requireIndex(n, model.nodeCount(), spec, "node");
      return source.reactions().col(n).norm();
    case Q::EndTension:
      requireIndex(spec.end, 2, spec, "end");
      return elementResult(spec, model, source).end_tension[spec.end];
    case Q::MaxTension:
      return maxTension(spec, model, source);
    case Q::Frequency:
    case Q::Period: {
      const std::vector<double>& omega = source.frequencies();
      requireIndex(spec.mode - 1, static_cast<int>(omega.size()), spec, "mode (0-based)");
      const double w = omega[spec.mode - 1];
      return spec.quantity == Q::Frequency ? w : 2.0 * std::acos(-1.0) / w;
    }
    case Q::ResultantMax:
      return principalResultants(spec, model, source).first;
    case Q::ResultantMin:
      return principalResultants(spec, model, source).second;
  }
  throw std::logic_error("summary \"" + spec.name + "\": unknown quantity");
}

}  // namespace

double evaluateSummary(const SummarySpec& spec, const model::Model& model,
                       const SummarySource& source) {
  return spec.scale * unscaled(spec, model, source);
}

double evaluateSummary(const SummarySpec& spec, const model::Model& model,
                       const ResultFrame& frame) {
  return evaluateSummary(spec, model, FrameSource(frame));
}

}  // namespace flexmoor::app
