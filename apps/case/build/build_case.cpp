#include "apps/case/build/build_case.hpp"

#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include "apps/case/build/build_conditions.hpp"
#include "apps/case/build/build_mesh.hpp"

namespace flexmoor::app {
namespace {

void requireNode(const MeshSpec& mesh, int node, const std::string& what) {
  if (node < 0 || node >= mesh.nodeCount())
    throw std::invalid_argument(what + ": node " + std::to_string(node) + " is not in the mesh (" +
                                std::to_string(mesh.nodeCount()) + " nodes, 0-based)");
}

// What the model would fail on: references to nodes it does not have, nothing to solve.
void check(const CaseSpec& spec) {
  for (int e = 0; e < spec.mesh.elementCount(); ++e)
    for (int node : spec.mesh.elementNodes(e))
      requireNode(spec.mesh, node, "element " + std::to_string(e));
  for (const SupportSpec& s : spec.conditions.supports) {
    requireNode(spec.mesh, s.node, "a support");
    if (s.component < 0 || s.component > 2)
      throw std::invalid_argument("a support of node " + std::to_string(s.node) + ": component " +
                                  std::to_string(s.component) + " (expected 0, 1 or 2: x, y, z)");
  }
  for (const NodalLoadSpec& l : spec.conditions.nodal_loads)
    requireNode(spec.mesh, l.node, "a load");
  for (const CaseLine& line : spec.lines)
    for (int node : line.nodes) requireNode(spec.mesh, node, "line " + line.name);
  if (spec.mesh.elementCount() == 0) throw std::invalid_argument("the case has no elements");
  if (spec.steps.empty()) throw std::invalid_argument("the case has no steps");
}

}  // namespace

Case buildCase(const CaseSpec& spec) {
  check(spec);
  Case c;
  c.name = spec.name;
  c.title = spec.title;
  c.file = spec.name;
  c.units = spec.units;
  c.model = std::make_unique<model::Model>();
  buildMesh(spec.mesh, *c.model);
  buildConditions(spec.conditions, *c.model);
  c.model->numberEquations();
  if (c.model->equationCount() == 0)
    throw std::invalid_argument("every dof is fixed (expected something to solve for)");
  c.node_ids.resize(c.model->nodeCount());
  std::iota(c.node_ids.begin(), c.node_ids.end(), 1);  // a case file's ids count from 1
  c.steps = spec.steps;
  c.summary = spec.summary;
  for (const CaseLine& line : spec.lines) {
    c.lines[line.name] = line.nodes;
    c.named_lines.push_back(line);
  }
  return c;
}

}  // namespace flexmoor::app
