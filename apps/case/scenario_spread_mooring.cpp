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
//   platform: {reference: [x, y, z], surge: {amplitude, period, phase}, sway, heave, roll,
//              pitch, yaw}  # optional: the fairleads carried by it (scenario_platform.hpp)
//   statics: {...}           # keys of the static step (default: one increment)
//   dynamic: {...}           # optional: a dynamic step after it
//   steps:, summary:, figure:, histories:   # the case's own, instead of the scenario's
//
// Line k (1-based) is `line_k` (line_1, line_2, ...): its anchor line_k.start, its fairlead
// line_k.end. The default
// summary: per line, fairlead_tension_k and anchor_tension_k (the force on the end point from the
// end element's nodal force balance, end_tension), fairlead_horizontal_k and fairlead_vertical_k
// (the fairlead support's reaction: the upward pull that holds the line), anchor_horizontal_k and
// anchor_vertical_k (the line's pull on the anchor, upward +: an uplift; a laid line's anchor,
// held at the bed's level, carries a little of the laid part's weight, a small negative value)
// and length_on_seabed_k.
//
// Each fairlead is a support of line_k.end with the displacement that takes the reference end to
// the fairlead (fairleadSupport below). With `platform:`, the fairleads are points of the rigid
// platform: each dof of the support follows a history of type rigid_point (named
// line_k.fairlead_x, _y, _z), the fairlead's rest position plus the platform's motion, its velocity
// and acceleration those of the rigid motion (v + omega x r); the statics hold the platform where
// the motion puts it at t = 0.
#include <cmath>
#include <optional>

#include "apps/case/scenario.hpp"
#include "apps/case/scenario_platform.hpp"
#include "apps/case/scenario_yaml.hpp"
#include "apps/case/units.hpp"
#include "apps/case/yaml_input.hpp"
#include "libhydro/mooring/catenary_line.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);
const QuantityKind kMassPerLength{"a mass per length (like kg/m)", {1, -1, 0}};
const QuantityKind kWeightPerLength{"a force per length (like N/m)", {1, 0, -2}};

// A line type as read: what its section and the catenary start need, and its hydro keys.
struct LineType {
  double area = 0.0, mass_per_length = 0.0, ea = 0.0, diameter = 0.0;
  YAML::Node node;  // its map in the file, for the keys copied with their place
};

struct MooringLine {
  Eigen::Vector3d anchor, fairlead;
  double length = 0.0;
  std::string type;
  int elements = 20, order = 3;
};

std::optional<LineType> readLineType(Input& in, const MapEntry& e, double rho, double g) {
  Diagnostics& diag = in.diag;
  Fields f(diag, e.value, childPath("line_types", e.key),
           {"diameter", "mass_per_length", "EA", "weight_in_water", "compression", "strain", "Cn",
            "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length", "damping"});
  const auto need = [&](const char* key, const QuantityKind& kind) {
    const YAML::Node* n = f.require(key);
    return n ? in.quantity(*n, f.path(key), kind, Limit::Positive) : std::nullopt;
  };
  const auto d = need("diameter", kind::kLength);
  const auto m = need("mass_per_length", kMassPerLength);
  const auto ea = need("EA", kind::kForce);
  if (!d || !m || !ea) return std::nullopt;
  LineType t{kPi * *d * *d / 4.0, *m, *ea, *d, e.value};
  if (const YAML::Node* n = f.find("weight_in_water")) {
    const auto w = in.quantity(*n, f.path("weight_in_water"), kWeightPerLength);
    const double expected = (t.mass_per_length - rho * t.area) * g;
    if (w && rho > 0.0 && std::abs(*w - expected) > 1e-3 * std::abs(expected)) {
      diag.error(*n, f.path("weight_in_water") +
                         ": does not match the mass and diameter in this water (got " +
                         formatNumber(*w) + ", expected " + formatNumber(expected) +
                         " = (mass_per_length - rho pi d^2 / 4) g, within 0.1%)");
      return std::nullopt;
    }
  }
  return t;
}

std::optional<MooringLine> readMooringLine(Input& in, const YAML::Node& item,
                                           const std::string& path) {
  Fields f(in.diag, item, path, {"anchor", "fairlead", "length", "type", "elements", "order"});
  MooringLine line;
  const YAML::Node* a = f.require("anchor");
  const YAML::Node* b = f.require("fairlead");
  const YAML::Node* l = f.require("length");
  const YAML::Node* t = f.require("type");
  const auto anchor = a ? in.vector3(*a, f.path("anchor"), kind::kLength) : std::nullopt;
  const auto fairlead = b ? in.vector3(*b, f.path("fairlead"), kind::kLength) : std::nullopt;
  const auto length =
      l ? in.quantity(*l, f.path("length"), kind::kLength, Limit::Positive) : std::nullopt;
  const auto type = t ? in.text(*t, f.path("type")) : std::nullopt;
  line.elements = in.integerOr(f, "elements", 1, 20);
  line.order = in.integerOr(f, "order", 2, 3);
  if (line.order > 4)
    in.diag.error(f.keyLine("order"), f.path("order") + ": out of range (got " +
                                          std::to_string(line.order) +
                                          ", expected 2, 3 or 4 nodes an element)");
  if (!anchor || !fairlead || !length || !type) return std::nullopt;
  line.anchor = *anchor;
  line.fairlead = *fairlead;
  line.length = *length;
  line.type = *type;
  return line;
}

// Whether the line can start: its ends in the water, above the bed, and its catenary solvable
// (the same inputs build_initial_shape.cpp gives it), reported at the line's item.
bool checkStart(Diagnostics& diag, const YAML::Node& item, const std::string& path,
                const MooringLine& line, const LineType& type, double rho, double g, double depth) {
  const double tolerance = 1e-6 * std::max(depth, line.length);
  for (const auto& [end, where] : {std::pair{&line.anchor, "anchor"}, {&line.fairlead, "fairlead"}})
    if (end->z() < -depth - tolerance) {
      diag.error(item,
                 path + "." + where + ": below the seabed (got z = " + formatNumber(end->z()) +
                     ", expected z >= " + formatNumber(-depth) + ", the bed at the water's depth)");
      return false;
    }
  hydro::CatenaryLineInputs in;
  const Eigen::Vector3d span = line.fairlead - line.anchor;
  in.horizontal_span = span.head<2>().norm();
  in.vertical_span = span.z();
  in.unstretched_length = line.length;
  in.weight = (type.mass_per_length - rho * type.area) * g;
  in.axial_stiffness = type.ea;
  in.seabed = line.anchor.z() <= -depth + tolerance;
  try {
    hydro::solveCatenary(in);
    return true;
  } catch (const hydro::CatenaryError& e) {
    diag.error(item, path + ": no catenary start: " + e.what());
    return false;
  }
}

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

YAML::Node summaryItem(const char* quantity, const char* key, const std::string& value,
                       const char* end = nullptr) {
  YAML::Node n;
  n["quantity"] = quantity;
  n[key] = value;
  if (end) n["end"] = end;
  return n;
}

}  // namespace

YAML::Node expandSpreadMooring(Diagnostics& diag, const YAML::Node& root) {
  const UnitSystem units = scenarioUnits(root);
  Input in(diag, units);
  std::vector<std::string> keys = {
      "name",     "title",   "units",   "scenario",  "water",      "gravity",
      "seabed",   "waves",   "current", "histories", "line_types", "mooring_lines",
      "platform", "statics", "dynamic", "steps",     "summary",    "figure"};
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
    auto line = readMooringLine(in, items[i], path);
    if (!line) continue;
    const auto type = types.find(line->type);
    if (type == types.end()) {
      if (!top.find("line_types") || !(*top.find("line_types"))[line->type]) {
        std::string names;
        for (const auto& entry : types) names += (names.empty() ? "" : ", ") + entry.first;
        diag.error(items[i]["type"], path + ".type: unknown line type (got '" + line->type +
                                         "', expected one of line_types: " +
                                         (names.empty() ? "none defined" : names) + ")");
      }
      continue;
    }
    if (diag.empty() && checkStart(diag, items[i], path, *line, type->second, rho, g, depth))
      lines.push_back(*line);
  }
  for (const char* key : {"statics", "dynamic"}) {
    const YAML::Node* n = top.find(key);
    if (n && top.find("steps"))
      diag.error(*n, std::string(key) +
                         ": given with steps: (expected the scenario's statics: and dynamic:, "
                         "or steps: of the case's own)");
    else if (n && !n->IsMap())
      diag.error(*n, std::string(key) + ": expected a map of the step's keys (got " +
                         describeNode(*n) + ")");
  }
  if (!diag.empty() || lines.size() != items.size()) return root;

  // The expanded document: the case's own keys, then what the scenario stands for.
  YAML::Node doc(YAML::NodeType::Map);
  for (const auto& key :
       {"name", "title", "units", "water", "waves", "current", "histories", "summary", "figure"})
    if (const YAML::Node* n = top.find(key)) doc[key] = *n;
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
  int elements_before = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const MooringLine& m = lines[i];
    const std::string name = "line_" + std::to_string(i + 1);
    // The reference: the unstretched length laid straight from the anchor towards the fairlead.
    Eigen::Vector3d along(m.fairlead.x() - m.anchor.x(), m.fairlead.y() - m.anchor.y(), 0.0);
    along.normalize();
    const Eigen::Vector3d end = m.anchor + m.length * along;
    YAML::Node line;
    line["name"] = name;
    line["from"] = point(m.anchor);
    line["to"] = point(end);
    line["elements"] = m.elements;
    line["order"] = m.order;
    line["section"] = m.type;
    line["initial_shape"] = "catenary";
    doc["lines"].push_back(line);
    YAML::Node anchor;
    anchor["node"] = name + ".start";
    anchor["fix"] = flowSequence({"x", "y", "z"});
    doc["supports"].push_back(anchor);
    addFairleadSupports(doc, name, end, m.fairlead, platform);
    if (!top.find("summary")) {
      const std::string k = std::to_string(i + 1);
      const std::string first = std::to_string(elements_before + 1);
      const std::string last = std::to_string(elements_before + m.elements);
      YAML::Node s = doc["summary"];
      s["fairlead_tension_" + k] = summaryItem("end_tension", "element", last, "last");
      s["fairlead_horizontal_" + k] = summaryItem("reaction_horizontal", "node", name + ".end");
      s["fairlead_vertical_" + k] = summaryItem("reaction_z", "node", name + ".end");
      s["anchor_tension_" + k] = summaryItem("end_tension", "element", first, "first");
      s["anchor_horizontal_" + k] = summaryItem("reaction_horizontal", "node", name + ".start");
      YAML::Node uplift = summaryItem("reaction_z", "node", name + ".start");
      uplift["scale"] = -1;  // the line's pull on the anchor, upward +
      s["anchor_vertical_" + k] = uplift;
      s["length_on_seabed_" + k] = summaryItem("length_on_seabed", "line", name);
    }
    elements_before += m.elements;
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
