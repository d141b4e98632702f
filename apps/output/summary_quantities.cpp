#include "apps/output/summary_quantities.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
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

// The unstretched length of a line whose weight the seabed carries: the bed's vertical force over
// the line, integrated at the elements' own integration points (the consistent nodal forces of
// the seabed load summed), plus the anchor's upward reaction when the anchor is held at the
// bed's level (the penalty bed carries the laid line a penetration below it, so the anchor
// holds the end of the laid part), over the submerged weight per length. A line on a rigid bed
// gives its laid length L_B; a fully suspended line 0. Each element counts over its own weight
// per length (the segments of a multi-segment line differ). In a static equilibrium under weight,
// buoyancy and the bed alone it equals L - V_F / w, with V_F the fairlead's vertical force.
double lengthOnSeabed(const SummarySpec& spec, const Case& c, const SummarySource& source) {
  const model::Model& model = *c.model;
  if (!c.seabed_contact)
    throw std::out_of_range("summary \"" + spec.name + "\": the model has no seabed contact");
  const model::LineLoad& bed = *model.lineLoads().at(*c.seabed_contact);
  double length = 0.0;  // each element's carried weight over its weight per length
  Eigen::VectorXd p;
  for (size_t i = 0; i < spec.elements.size(); ++i) {
    const int e = spec.elements[i];
    requireIndex(e, model.elementCount(), spec, "element");
    model.element(e).lineLoad({model.reference(), source.state(), e}, bed, p, nullptr);
    double carried = 0.0;
    for (Eigen::Index a = 2; a < p.size(); a += 3) carried += p(a);
    length += carried / spec.element_weights.at(i);
  }
  length *= source.state().load_factor;  // line loads act scaled by it
  if (spec.node >= 0)
    length += std::max(source.reactions()(2, spec.node), 0.0) / spec.weight_per_length;
  return length;
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

double unscaled(const SummarySpec& spec, const Case& c, const SummarySource& source) {
  using Q = SummarySpec::Quantity;
  const model::Model& model = *c.model;
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
    case Q::ReactionHorizontal:
      requireIndex(n, model.nodeCount(), spec, "node");
      return source.reactions().col(n).head<2>().norm();
    case Q::LengthOnSeabed:
      return lengthOnSeabed(spec, c, source);
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
    case Q::CpuSeconds:  // the whole run's, read, steps and writing, at the summary's evaluation
      return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
  }
  throw std::logic_error("summary \"" + spec.name + "\": unknown quantity");
}

}  // namespace

double evaluateSummary(const SummarySpec& spec, const Case& c, const SummarySource& source) {
  return spec.scale * unscaled(spec, c, source);
}

double evaluateSummary(const SummarySpec& spec, const Case& c, const ResultFrame& frame) {
  return evaluateSummary(spec, c, FrameSource(frame));
}

}  // namespace flexmoor::app
