// The scenarios read into specifications: the reader builds on the case each stands for.
#include "apps/case/scenarios/scenario_model.hpp"

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

const char* elementType(ElementSpec::Kind kind) {
  switch (kind) {
    case ElementSpec::Kind::Cable:
      return "cable";
    case ElementSpec::Kind::PointMass:
      return "point_mass";
    case ElementSpec::Kind::Spring:
      return "spring";
    case ElementSpec::Kind::HoopCable:
      return "hoop_cable";
    case ElementSpec::Kind::AxisymmetricMembrane:
      return "axisymmetric_membrane";
    case ElementSpec::Kind::MembraneTriangle:
    case ElementSpec::Kind::MembraneQuad:
      return "membrane";
  }
  return "";
}

const SpecScenario kScenarios[] = {
    {"single_point_moor", singlePointMoorKeys, readSinglePointMoor, addSinglePointMoorDefaults},
    {"spread_mooring", spreadMooringKeys, readSpreadMooring, addSpreadMooringDefaults},
};

}  // namespace

const SpecScenario* specScenarioOf(const YAML::Node& root) {
  if (!root.IsMap() || !root["scenario"] || !root["scenario"].IsScalar()) return nullptr;
  for (const SpecScenario& s : kScenarios)
    if (root["scenario"].Scalar() == s.name) return &s;
  return nullptr;
}

std::vector<std::string> specScenarioNames() {
  std::vector<std::string> names;
  for (const SpecScenario& s : kScenarios) names.push_back(s.name);
  return names;
}

void addScenarioModel(CaseBuilder& b, const ScenarioModel& model) {
  const CaseSpec& s = model.spec;
  b.mesh = s.mesh;
  b.origins = model.origins;
  for (int node = 0; node < s.mesh.nodeCount(); ++node) {
    b.c.node_ids.push_back(node + 1);
    b.node_of_id[node + 1] = node;
  }
  for (const ElementSpec& e : s.mesh.elements) b.element_types.push_back(elementType(e.kind));
  for (const CaseLine& line : s.lines) {
    b.c.lines[line.name] = line.nodes;
    b.c.named_lines.push_back(line);
    b.line_elements[line.name] = line.elements;
    b.line_order.push_back(line.name);
    if (line.anchor != CaseLine::Anchor::None) b.line_anchors[line.name] = line.anchor;
    if (!line.segment_of.empty()) ++b.line_segments[line.segment_of];
  }
  b.conditions = s.conditions;
  for (size_t i = 0; i < s.conditions.supports.size(); ++i) {
    const SupportSpec& support = s.conditions.supports[i];
    b.first_support.emplace(3LL * support.node + support.component, i);
  }
  b.gravity_given = s.conditions.gravity.has_value();
  b.c.rigid_motions = s.rigid_motions;
  b.histories = s.histories;
  b.catenary_starts = s.catenary_starts;
}

void addScenarioOcean(CaseBuilder& b, const ScenarioModel& model, bool seabed_given) {
  const OceanSpec& ocean = model.spec.ocean;
  b.ocean.morison = ocean.morison;
  b.ocean.bodies = ocean.bodies;
  if (seabed_given || !ocean.has_contact) return;
  b.ocean.has_contact = true;
  b.ocean.contact = ocean.contact;
}

void readScenarioSteps(CaseBuilder& b, Fields& top, const ScenarioModel& model) {
  if (const YAML::Node* steps = top.find("steps")) {
    readSteps(b, *steps);
    return;
  }
  for (const ScenarioStep& step : model.steps) {
    const YAML::Node* keys = top.find(step.key);
    if (keys || step.always) readStepOf(b, step.base, keys, step.key, step.base.name);
  }
}

}  // namespace flexmoor::app
