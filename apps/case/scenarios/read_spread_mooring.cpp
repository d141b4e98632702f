// scenario: spread_mooring in a case file: its own keys read into a SpreadMooringSpec, and the
// case the spec states put where the reader reads the case's other sections on top of it
// (spread_mooring.hpp has the model):
//
//   scenario: spread_mooring
//   water: {density: 1025 kg/m^3, depth: 320 m}   # required
//   gravity: 9.80665 m/s^2                         # default: standard gravity
//   seabed: {stiffness, damping, friction, ...}    # default: MoorDyn's kBot, cBot, no friction
//   line_types:                                    # one section each
//     chain: {diameter, mass_per_length, EA, weight_in_water (a check), compression,
//             strain: engineering (the catenary's and MoorDyn's law; or green, Eq. 2.53),
//             Cn, Ct, Ca, CaAx, tangential_drag_area, per_length,
//             damping: {BA: N*s} (axial Kelvin-Voigt, MoorDyn's BA; or {zeta: ...})}
//   mooring_lines:
//     - {anchor: [x, y, z], fairlead: [x, y, z], length, type: chain, elements: 20, order: 3}
//     - {anchor: [x, y, z], fairlead: [x, y, z],            # segments from the anchor up
//        segments: [{type: chain, length: 100 m, elements: 6}, {type: wire, length: 600 m,
//                   elements: 10}, {type: chain, length: 135 m, elements: 4, order: 4}],
//        attachments: [{at: 1, mass: 5000 kg, volume: 2 m^3, drag_area: 1 m^2, Ca: 0.5}]}
//   platform: {reference: [x, y, z], surge: {amplitude, period, phase}, sway, heave, roll,
//              pitch, yaw}  # optional: the fairleads carried by it (platform.hpp)
//   statics: {...}           # keys of the static step (default: one increment)
//   dynamic: {...}           # optional: a dynamic step after it
//   steps:, summary:, figure:, histories:   # the case's own, instead of the scenario's
//   waves:, current:, output:                # as in any case
//
// Line k's items speak of the line in messages ("mooring_lines[0]"); the fairleads' histories
// are line_k.fairlead_x, _y, _z and the platform's motion `platform`, which the case's own
// histories may share (rigid_point with motion: platform).
#include <algorithm>

#include "apps/case/case_builder.hpp"
#include "apps/case/scenarios/scenario_keys.hpp"
#include "apps/case/scenarios/scenario_model.hpp"
#include "apps/case/scenarios/spread_mooring.hpp"

namespace flexmoor::app {
namespace {

// Where each node and element of the scenario's model comes from: the item of its line.
ModelOrigins originsOf(const SpreadMooringSpec& spec, const CaseSpec& c,
                       const std::vector<int>& item_lines) {
  ModelOrigins origins = ModelOrigins::sourceless(c.mesh.nodeCount(), c.mesh.elementCount());
  int point_mass = 0;  // the attachments' point masses come first, in the lines' order
  for (size_t i = 0; i < spec.lines.size(); ++i) {
    const std::string where = itemPath("mooring_lines", i);
    for (size_t j = 0; j < spec.lines[i].attachments.size(); ++j)
      if (spec.lines[i].attachments[j].mass > 0.0)
        origins.elements[point_mass++] = {item_lines[i], itemPath(where + ".attachments", j), ""};
  }
  size_t i = 0;
  for (const CaseLine& line : c.lines) {
    if (!line.segment_of.empty()) continue;
    const MooringLine& m = spec.lines[i];
    size_t e = 0;
    for (const MooringSegment& segment : m.segments)
      for (int k = 0; k < segment.elements; ++k)
        origins.elements[line.elements[e++]] = {item_lines[i], itemPath("mooring_lines", i),
                                                segment.type};
    for (const int node : line.nodes) origins.node_lines[node] = item_lines[i];
    ++i;
  }
  return origins;
}

}  // namespace

const std::vector<std::string>& spreadMooringKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = {
        "name",    "title",   "units",     "scenario",   "water",         "gravity",  "seabed",
        "waves",   "current", "histories", "line_types", "mooring_lines", "platform", "statics",
        "dynamic", "steps",   "summary",   "figure",     "output"};
    k.insert(k.end(), scenarioGeneratedKeys().begin(), scenarioGeneratedKeys().end());
    return k;
  }();
  return keys;
}

std::optional<ScenarioModel> readSpreadMooring(CaseBuilder& b, Fields& top) {
  Diagnostics& diag = b.diag;
  refuseGeneratedKeys(diag, top, "spread_mooring", "line_types: and mooring_lines:,");
  const ScenarioWater water = readScenarioWater(b.in, top, b.in.units);
  const double rho = water.density, depth = water.depth, g = water.gravity;
  SpreadMooringSpec spec;
  spec.units = b.in.units;
  spec.water = {rho, depth, g};
  if (const YAML::Node* n = top.find("platform")) {
    spec.platform = readPlatform(b, *n);
    if (const YAML::Node* h = top.find("histories"); h && (*h)["platform"])
      diag.error((*h)["platform"],
                 "histories.platform: the name of the platform's motion in a "
                 "spread mooring (expected another name)");
  }
  if (const YAML::Node* n = top.require("line_types"))
    for (const MapEntry& e : mapEntries(diag, *n, "line_types"))
      if (auto t = readLineType(b, e, rho, g)) spec.line_types.emplace(e.key, *t);
  const YAML::Node* list = top.require("mooring_lines");
  const std::vector<YAML::Node> items =
      list ? listItems(diag, *list, "mooring_lines") : std::vector<YAML::Node>();
  if (list && items.empty()) diag.error(*list, "mooring_lines: empty (expected at least one line)");
  std::vector<int> item_lines;
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string path = itemPath("mooring_lines", i);
    const auto line =
        readMooringLine(b.in, items[i], path, spec.line_types, top.find("line_types"));
    if (line && diag.empty() &&
        checkStart(diag, items[i], path, *line, spec.line_types, rho, g, depth)) {
      spec.lines.push_back(*line);
      item_lines.push_back(lineOf(items[i]));
    }
  }
  checkScenarioStepKeys(diag, top, {"statics", "dynamic"});
  if (!diag.empty() || spec.lines.size() != items.size()) return std::nullopt;
  ScenarioModel model{spreadMooring(spec), {}, {}, spreadMooringSummary};
  model.origins = originsOf(spec, model.spec, item_lines);
  StepSpec dynamic;
  dynamic.kind = StepSpec::Kind::Dynamic;
  dynamic.name = "dynamic";
  model.steps = {{"statics", spreadMooringStatics(), true}, {"dynamic", dynamic, false}};
  return model;
}

}  // namespace flexmoor::app
