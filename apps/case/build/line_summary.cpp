#include "apps/case/build/line_summary.hpp"

#include "apps/case/build/build_initial_shape.hpp"

namespace flexmoor::app {

int seabedLine(const CaseLine& line, const MeshSpec& mesh, const ConditionsSpec& held,
               const OceanSpec& ocean, SummarySpec& s) {
  const std::vector<const LineHydroSpec*> hydro = ocean.elementHydro(mesh.elementCount());
  s.quantity = SummarySpec::Quantity::LengthOnSeabed;
  s.elements = line.elements;
  s.element_weights.clear();
  const double g = held.gravityVector().norm();
  for (size_t i = 0; i < line.elements.size(); ++i) {
    const int e = line.elements[i];
    const double w = submergedWeightPerLength(ocean, g, mesh.elements[e].cable_section,
                                              hydro[e] ? hydro[e]->coefficients.diameter : 0.0);
    s.element_weights.push_back(w);
    if (!(w > 0.0)) return static_cast<int>(i);
  }
  const model::NodalField& X = mesh.reference;
  const auto height = [&](int node) {  // where its supports put it, at load factor 1
    return X(2, node) + held.prescribed(node, 2);
  };
  const std::vector<int>& nodes = line.nodes;
  const int lower = height(nodes.front()) <= height(nodes.back()) ? nodes.front() : nodes.back();
  const double bed = ocean.bed.height(X(0, lower) + held.prescribed(lower, 0),
                                      X(1, lower) + held.prescribed(lower, 1));
  const bool at_bed = height(lower) <= bed + mesh.positionTolerance();
  s.node = held.held(lower, 2) && at_bed ? lower : -1;
  // The weight of the element at the anchor, for the anchor's share of the laid weight.
  s.weight_per_length = s.element_weights.front();
  for (size_t i = 0; i < s.elements.size(); ++i) {
    const std::vector<int>& ends = mesh.elementNodes(s.elements[i]);
    if (ends.front() == lower || ends.back() == lower) s.weight_per_length = s.element_weights[i];
  }
  return -1;
}

}  // namespace flexmoor::app
