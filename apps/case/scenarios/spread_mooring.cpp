// scenario: spread_mooring: N mooring lines from anchors to fairlead points, in water with seabed
// contact. Each line's reference is the straight line of its unstretched length laid along the
// bed from its anchor towards its fairlead; it starts on its elastic catenary with seabed contact
// (lines' initial_shape: catenary, libhydro/mooring/catenary_line.hpp), its fairlead held where
// the case puts it, and a static Newton step finds the FE equilibrium from there. OC3-Hywind and
// OC4-DeepCwind (cases/ocean) are such cases.
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
//              pitch, yaw}  # optional: the fairleads carried by it (platform.hpp);
//                           # each motion a sine, {table: [[t, value], ...]} or
//                           # {file: motion.csv, column: surge} (read_motion.hpp)
//   statics: {...}           # keys of the static step (default: one increment)
//   dynamic: {...}           # optional: a dynamic step after it
//   steps:, summary:, figure:, histories:   # the case's own, instead of the scenario's
//
// A line of segments (mooring_lines.hpp) is the segments line_k_segment_1, ... of line
// line_k (`segment_of: line_k`, each starting at the end of the one before), starting on the
// multi-segment catenary of the whole line; each attachment at connection k (between segments k
// and k + 1, at line_k_segment_k.end) is a point_mass element of its mass (elements:, numbered
// before the lines' cables) and a point body of its volume (bodies: type point, with its
// drag_area and Ca): a net upward force (rho V - m) g, with the body's Morison loads in motion.
//
// Line k (1-based) is `line_k` (line_1, line_2, ...), a mooring line (`anchor: start`): its
// anchor line_k.start (line_k.anchor), its fairlead line_k.end (line_k.fairlead). The default
// summary, per line, in the state that closes the static step (the scenario's equilibrium, or
// with steps: of the case's own the last step before the first dynamic one):
// fairlead_tension_static_k and anchor_tension_static_k (the force on the end point from the end
// element's nodal force balance, end_tension; the first is the line's pretension),
// fairlead_horizontal_static_k and fairlead_vertical_static_k (the fairlead support's reaction:
// the upward pull that holds the line), anchor_horizontal_static_k and anchor_vertical_static_k
// (the line's pull on the anchor, upward +: an uplift; a laid line's anchor, held at the bed's
// level, carries a little of the laid part's weight, a small negative value) and
// length_on_seabed_static_k; with a dynamic step, over the last one: fairlead_tension_max_k,
// fairlead_tension_min_k, anchor_tension_max_k and anchor_vertical_max_k (the largest uplift).
//
// Each fairlead is a support of line_k.end with the displacement that takes the reference end to
// the fairlead (fairleadSupport below). With `platform:`, the fairleads are points of the rigid
// platform, whose motion is the history `platform` of type rigid_motion: each dof of the support
// follows a history of type rigid_point of it (named line_k.fairlead_x, _y, _z), the fairlead's
// rest position plus the platform's motion, its velocity
// and acceleration those of the rigid motion (v + omega x r); the statics hold the platform where
// the motion puts it at t = 0.
#include <cmath>
#include <optional>

#include "apps/case/input/units.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/case/scenarios/mooring_lines.hpp"
#include "apps/case/scenarios/platform.hpp"
#include "apps/case/scenarios/scenario.hpp"
#include "apps/case/scenarios/yaml_text.hpp"

namespace flexmoor::app {
namespace {

YAML::Node point(const Eigen::Vector3d& p) {
  return flowSequence({scenarioNumber(p.x()), scenarioNumber(p.y()), scenarioNumber(p.z())});
}

// The fairlead's supports: line_k.end held at the fairlead (its reference end moved there), or
// each of its dofs carried by the platform (displacement 1 times its history, in length units).
void addFairleadSupports(YAML::Node& doc, const std::string& name,
                         const Eigen::Vector3d& reference_end, const Eigen::Vector3d& fairlead,
                         const std::optional<PlatformMotion>& platform) {
  if (!platform) {
    YAML::Node s;
    s["node"] = name + ".end";
    s["fix"] = flowSequence({"x", "y", "z"});
    s["displacement"] = point(fairlead - reference_end);
    doc["supports"].push_back(s);
    return;
  }
  for (int k = 0; k < 3; ++k) {
    const std::string axis(1, "xyz"[k]);
    const std::string history = name + ".fairlead_" + axis;
    doc["histories"][history] = platformPointHistory(*platform, fairlead, reference_end, k);
    YAML::Node s;
    s["node"] = name + ".end";
    s["fix"] = flowSequence({axis});
    s["displacement"] = flowSequence({"1"});
    s["history"] = history;
    doc["supports"].push_back(s);
  }
}

// The lines: of mooring line `name`: its reference the unstretched length laid straight from the
// anchor towards the fairlead, one line of its type, or its segments (name_segment_1, ...; each a
// segment_of: name) with the attachments' point masses (elements:) and bodies (bodies:) at their
// connection nodes. Returns the reference's end.
Eigen::Vector3d addLine(YAML::Node& doc, const std::string& name, const MooringLine& m) {
  Eigen::Vector3d along(m.fairlead.x() - m.anchor.x(), m.fairlead.y() - m.anchor.y(), 0.0);
  along.normalize();
  const auto segmentName = [&](size_t j) { return name + "_segment_" + std::to_string(j + 1); };
  double s = 0.0;
  for (size_t j = 0; j < m.segments.size(); ++j) {
    const MooringSegment& segment = m.segments[j];
    YAML::Node line;
    line["name"] = m.has_segments ? segmentName(j) : name;
    if (j == 0)
      line["from"] = point(m.anchor);
    else
      line["start_node"] = segmentName(j - 1) + ".end";
    s += segment.length;
    line["to"] = point(m.anchor + s * along);
    line["elements"] = segment.elements;
    line["order"] = segment.order;
    line["section"] = segment.type;
    line["initial_shape"] = "catenary";
    line["anchor"] = "start";  // of the whole line, for a segment
    if (m.has_segments) line["segment_of"] = name;
    doc["lines"].push_back(line);
  }
  for (const MooringAttachment& a : m.attachments) {
    const std::string node = segmentName(a.at - 1) + ".end";
    if (a.mass > 0.0) {
      YAML::Node mass;
      mass["type"] = "point_mass";
      mass["node"] = node;
      mass["mass"] = scenarioNumber(a.mass);
      doc["elements"].push_back(mass);
    }
    if (a.volume > 0.0) {
      YAML::Node body;
      body["node"] = node;
      body["type"] = "point";
      body["volume"] = scenarioNumber(a.volume);
      if (a.drag_area) body["drag_area"] = *a.drag_area;
      if (a.added_mass) body["Ca"] = *a.added_mass;
      doc["bodies"].push_back(body);
    }
  }
  return m.anchor + s * along;
}

// One summary entry of line `line`: a quantity at one of its ends, at the close of step
// `step` (1-based) or, with `stat`, over it.
YAML::Node lineSummary(const char* quantity, const std::string& line, const char* end, int step,
                       const char* stat = nullptr) {
  YAML::Node n;
  n["quantity"] = quantity;
  n["line"] = line;
  if (end) n["end"] = end;
  n["step"] = step;
  if (stat) n["stat"] = stat;
  return n;
}

// The steps the default summary reads (1-based; 0 for none): the static one, the last step
// before the first dynamic step (or the last step when none is dynamic), and the last dynamic.
struct SummarySteps {
  int statics = 0, dynamic = 0;
};

SummarySteps summarySteps(const YAML::Node* steps, bool dynamic) {
  if (!steps) return {1, dynamic ? 2 : 0};  // the scenario's equilibrium, then its dynamic:
  SummarySteps s;
  int index = 0;
  bool before_dynamic = true;
  for (const YAML::Node& item : *steps) {
    ++index;
    const bool is_dynamic = item.IsMap() && item["dynamic"];
    if (is_dynamic) {
      before_dynamic = false;
      s.dynamic = index;
    } else if (before_dynamic) {
      s.statics = index;
    }
  }
  return s;
}

// The default summary of line `name` (line k): the state closing the static step (_static_k)
// and, with a dynamic step, the fairlead tension's extremes, the anchor tension's largest value
// and the anchor's largest uplift over it (_max_k, _min_k).
void addLineSummary(YAML::Node summary, const std::string& name, const std::string& k,
                    SummarySteps steps) {
  if (steps.statics > 0) {
    const int st = steps.statics;
    summary["fairlead_tension_static_" + k] = lineSummary("end_tension", name, "fairlead", st);
    summary["fairlead_horizontal_static_" + k] =
        lineSummary("reaction_horizontal", name, "fairlead", st);
    summary["fairlead_vertical_static_" + k] = lineSummary("reaction_z", name, "fairlead", st);
    summary["anchor_tension_static_" + k] = lineSummary("end_tension", name, "anchor", st);
    summary["anchor_horizontal_static_" + k] =
        lineSummary("reaction_horizontal", name, "anchor", st);
    YAML::Node uplift = lineSummary("reaction_z", name, "anchor", st);
    uplift["scale"] = -1;  // the line's pull on the anchor, upward +
    summary["anchor_vertical_static_" + k] = uplift;
    summary["length_on_seabed_static_" + k] = lineSummary("length_on_seabed", name, nullptr, st);
  }
  if (steps.dynamic > 0) {
    const int dy = steps.dynamic;
    summary["fairlead_tension_max_" + k] = lineSummary("end_tension", name, "fairlead", dy, "max");
    summary["fairlead_tension_min_" + k] = lineSummary("end_tension", name, "fairlead", dy, "min");
    summary["anchor_tension_max_" + k] = lineSummary("end_tension", name, "anchor", dy, "max");
    YAML::Node uplift = lineSummary("reaction_z", name, "anchor", dy, "max");
    uplift["scale"] = -1;
    summary["anchor_vertical_max_" + k] = uplift;
  }
}

}  // namespace

YAML::Node expandSpreadMooring(Diagnostics& diag, const YAML::Node& root) {
  const UnitSystem units = scenarioUnits(root);
  Input in(diag, units);
  std::vector<std::string> keys = {
      "name",    "title",   "units",     "scenario",   "water",         "gravity",  "seabed",
      "waves",   "current", "histories", "line_types", "mooring_lines", "platform", "statics",
      "dynamic", "steps",   "summary",   "figure",     "output"};
  keys.insert(keys.end(), scenarioGeneratedKeys().begin(), scenarioGeneratedKeys().end());
  Fields top(diag, root, "", keys);
  refuseGeneratedKeys(diag, top, "spread_mooring", "line_types: and mooring_lines:,");
  const ScenarioWater water = readScenarioWater(in, top, units);
  const double rho = water.density, depth = water.depth, g = water.gravity;

  std::optional<PlatformMotion> platform;
  if (const YAML::Node* n = top.find("platform")) platform = readPlatform(in, *n);
  std::map<std::string, LineType> types;
  if (const YAML::Node* n = top.require("line_types"))
    for (const MapEntry& e : mapEntries(diag, *n, "line_types"))
      if (auto t = readLineType(in, e, rho, g)) types.emplace(e.key, *t);
  std::vector<MooringLine> lines;
  const YAML::Node* list = top.require("mooring_lines");
  const std::vector<YAML::Node> items =
      list ? listItems(diag, *list, "mooring_lines") : std::vector<YAML::Node>();
  if (list && items.empty()) diag.error(*list, "mooring_lines: empty (expected at least one line)");
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string path = itemPath("mooring_lines", i);
    const auto line = readMooringLine(in, items[i], path, types, top.find("line_types"));
    if (line && diag.empty() && checkStart(diag, items[i], path, *line, types, rho, g, depth))
      lines.push_back(*line);
  }
  checkScenarioStepKeys(diag, top, {"statics", "dynamic"});
  if (!diag.empty() || lines.size() != items.size()) return root;

  // The expanded document: the case's own keys, then what the scenario stands for.
  YAML::Node doc(YAML::NodeType::Map);
  for (const auto& key : {"name", "title", "units", "water", "waves", "current", "histories",
                          "summary", "figure", "output"})
    if (const YAML::Node* n = top.find(key)) doc[key] = *n;
  if (!top.find("figure")) doc["figure"]["kind"] = "mooring";  // the tensions and the profiles
  doc["seabed"] = top.find("seabed") ? *top.find("seabed") : YAML::Node(YAML::NodeType::Map);
  for (const auto& [name, t] : types) {
    YAML::Node material, section, hydro;
    material["type"] = "linear_elastic";
    material["E"] = scenarioNumber(t.ea / t.area);  // EA over pi d^2 / 4
    material["strain"] = t.node["strain"] ? t.node["strain"] : YAML::Node("engineering");
    if (const YAML::Node c = t.node["compression"]) material["compression"] = c;
    doc["materials"][name] = material;
    section["material"] = name;
    section["area"] = scenarioNumber(t.area);
    section["density"] = scenarioNumber(t.mass_per_length / t.area);
    hydro["diameter"] = t.node["diameter"];
    for (const char* key : {"Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"})
      if (const YAML::Node v = t.node[key]) hydro[key] = v;
    section["hydro"] = hydro;
    if (const YAML::Node damping = t.node["damping"]) section["damping"] = damping;
    doc["sections"][name] = section;
  }
  const SummarySteps summary_steps = summarySteps(top.find("steps"), top.find("dynamic"));
  for (size_t i = 0; i < lines.size(); ++i) {
    const MooringLine& m = lines[i];
    const std::string name = "line_" + std::to_string(i + 1);
    const Eigen::Vector3d end = addLine(doc, name, m);
    YAML::Node anchor;
    anchor["node"] = name + ".start";
    anchor["fix"] = flowSequence({"x", "y", "z"});
    doc["supports"].push_back(anchor);
    addFairleadSupports(doc, name, end, m.fairlead, platform);
    if (!top.find("summary"))
      addLineSummary(doc["summary"], name, std::to_string(i + 1), summary_steps);
  }
  if (platform) {
    if (const YAML::Node* h = top.find("histories"); h && (*h)["platform"])
      diag.error((*h)["platform"], "histories.platform: the name of the platform's motion in a "
                                   "spread mooring (expected another name)");
    doc["histories"]["platform"] = platformMotionHistory(*platform);
  }
  doc["loads"]["gravity"]["g"] = scenarioNumber(g);
  if (const YAML::Node* steps = top.find("steps")) {
    doc["steps"] = *steps;
  } else {
    // Newton from the catenaries at the full load: one increment, the load factor already 1.
    YAML::Node statics(YAML::NodeType::Map);
    statics["name"] = "equilibrium";
    statics["increments"] = 1;
    if (const YAML::Node* n = top.find("statics"))
      for (const auto& kv : *n) statics[kv.first.Scalar()] = kv.second;
    YAML::Node step;
    step["static"] = statics;
    doc["steps"].push_back(step);
    if (const YAML::Node* n = top.find("dynamic")) {
      YAML::Node dynamic_step;
      dynamic_step["dynamic"] = *n;
      doc["steps"].push_back(dynamic_step);
    }
  }
  return doc;
}

}  // namespace flexmoor::app
