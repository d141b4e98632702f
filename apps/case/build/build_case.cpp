#include "apps/case/build/build_case.hpp"

#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>

#include "apps/case/build/build_conditions.hpp"
#include "apps/case/build/build_enclosed_fluid.hpp"
#include "apps/case/build/build_initial_shape.hpp"
#include "apps/case/build/build_mesh.hpp"
#include "apps/case/build/build_ocean.hpp"
#include "apps/case/check/model_checks.hpp"

namespace flexmoor::app {
namespace {

void requireNode(const MeshSpec& mesh, int node, const std::string& what) {
  if (node < 0 || node >= mesh.nodeCount())
    throw std::invalid_argument(what + ": node " + std::to_string(node) + " is not in the mesh (" +
                                std::to_string(mesh.nodeCount()) + " nodes, 0-based)");
}

void requireElement(const MeshSpec& mesh, int element, const std::string& what) {
  if (element < 0 || element >= mesh.elementCount())
    throw std::invalid_argument(what + ": element " + std::to_string(element) +
                                " is not in the mesh (" + std::to_string(mesh.elementCount()) +
                                " elements, 0-based)");
}

// The ocean's nodes and elements in the mesh, nothing without water.
void checkOcean(const OceanSpec& ocean, const MeshSpec& mesh) {
  if (!ocean.has_water) {
    if (!ocean.morison.empty() || !ocean.bodies.empty() || !ocean.wave_pressures.empty())
      throw std::invalid_argument(
          "the ocean's loads need its water (got Morison loads, bodies or wave pressure without "
          "has_water, expected OceanSpec::inWater)");
    return;
  }
  for (const MorisonSpec& m : ocean.morison)
    for (int e : m.elements) requireElement(mesh, e, "Morison loads");
  for (const BodySpec& body : ocean.bodies) requireNode(mesh, body.node, "a body");
  for (const WavePressureSpec& w : ocean.wave_pressures)
    for (int e : w.elements) requireElement(mesh, e, "wave pressure");
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
  checkOcean(spec.ocean, spec.mesh);
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
  c.node_ids.resize(c.model->nodeCount());
  std::iota(c.node_ids.begin(), c.node_ids.end(), 1);  // a case file's ids count from 1
  // The problems found, as a case file's: "<name>: element 4 (...): ...".
  Diagnostics diag(spec.name);
  for (const SpecError& e : buildEnclosedFluids(spec.enclosed_fluids, c))
    diag.error(e.line, e.message);
  const auto refuse = [&diag] {
    std::string messages;
    for (const std::string& m : diag.messages()) messages += (messages.empty() ? "" : "\n") + m;
    throw std::invalid_argument(messages);
  };
  if (!diag.empty()) refuse();
  c.model->numberEquations();
  if (c.model->equationCount() == 0)
    throw std::invalid_argument("every dof is fixed (expected something to solve for)");
  c.rigid_motions = spec.rigid_motions;
  c.steps = spec.steps;
  c.summary = spec.summary;
  c.output = spec.output;
  c.figure = spec.figure;
  c.element_sets = spec.element_sets;
  for (const CaseLine& line : spec.lines) {
    c.lines[line.name] = line.nodes;
    c.named_lines.push_back(line);
  }
  // The case file's checks of the built model.
  ModelOrigins origins = ModelOrigins::sourceless(spec.mesh.nodeCount(), spec.mesh.elementCount());
  origins.elements.resize(c.model->elementCount(), {0, "an enclosed liquid's lumped mass", ""});
  checkModel({c, spec.mesh, spec.ocean, origins, spec.surfaces, spec.histories, diag});
  for (const SpecError& e : diag.empty() ? startOnCatenaries(spec.catenary_starts, spec.ocean, c)
                                         : std::vector<SpecError>())
    diag.error(e.line, e.message);
  if (!diag.empty()) refuse();
  buildOcean(spec.ocean, c);
  c.warnings = diag.warnings();
  return c;
}

}  // namespace flexmoor::app
