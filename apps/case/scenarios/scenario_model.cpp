// The scenarios, and what the reader does with the case each stands for.
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

const Scenario kScenarios[] = {
    {"single_point_moor", singlePointMoorKeys, readSinglePointMoor},
    {"spread_mooring", spreadMooringKeys, readSpreadMooring},
    {"submerged_tube", submergedTubeKeys, readSubmergedTube},
};

}  // namespace

const Scenario* scenarioOf(Diagnostics& diag, const YAML::Node& root) {
  if (!root.IsMap() || !root["scenario"]) return nullptr;
  const YAML::Node name = root["scenario"];
  std::string names;
  for (const Scenario& s : kScenarios) {
    if (name.IsScalar() && name.Scalar() == s.name) return &s;
    names += (names.empty() ? "" : " | ") + std::string(s.name);
  }
  diag.error(name, "scenario: unknown (got " + describeNode(name) + ", expected " + names + ")");
  return nullptr;
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
  b.surfaces = s.surfaces;
  b.c.element_sets = s.element_sets;
  // The liquids as read from a case file, resolved with the others once the water is read.
  for (const EnclosedFluidSpec& f : s.enclosed_fluids) {
    PendingEnclosedFluid pending;
    pending.elements = f.elements;
    pending.density = f.fluid.density;
    pending.pressure = f.fluid.pressure;
    pending.at_z = f.fluid.reference_z;
    pending.line = f.line;
    pending.where = f.where;
    b.enclosed_fluids.push_back(std::move(pending));
  }
}

void addScenarioOcean(CaseBuilder& b, const ScenarioModel& model, bool seabed_given) {
  const OceanSpec& ocean = model.spec.ocean;
  b.ocean.morison = ocean.morison;
  b.ocean.bodies = ocean.bodies;
  b.ocean.wave_pressures = ocean.wave_pressures;
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

void addScenarioDefaults(CaseBuilder& b, Fields& top, const ScenarioModel& model) {
  if (!top.find("summary")) {
    CaseSpec read = model.spec;  // as the case has it: its ocean, its steps
    read.ocean = b.ocean;
    read.steps = b.c.steps;
    b.c.summary = model.summary(read);
    for (SummarySpec& s : b.c.summary) s.where = {b.diag.file(), 0};
  }
  if (top.find("figure") || !model.spec.figure) return;
  FigureSpec figure = *model.spec.figure;
  figure.where = {b.diag.file(), 0};
  if (figure.kind == FigureSpec::Kind::Series) {
    std::vector<std::string> written;
    for (const std::string& series : figure.series) {
      const auto field = OutputFields::ofVariable(series.substr(0, series.find('@')));
      if (field && b.c.output.has(*field)) written.push_back(series);
    }
    if (written.empty()) return;
    figure.series = written;
  }
  b.c.figure = figure;
}

}  // namespace flexmoor::app
