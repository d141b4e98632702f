// scenario: single_point_moor: an anchor, a rope or cable, and a buoy at its end, in water; the
// buoy is held at a given position while viscous relaxation finds the line's displaced shape,
// then released (its support removed: its buoyancy, weight and the line's pull act) and the
// motion integrated in time. The dissertation's Example 8 is one. The model is planar (x-z).
//
//   scenario: single_point_moor
//   water: {density: 1.94364 slug/ft^3, depth: 80 in}     # required
//   anchor: [0, 0, -80 in]         # default: on the bed below the origin
//   cable: {length, EA, weight_in_air, weight_in_water (a check), diameter, elements: 4,
//           order: 3, Cn, Ct, Ca, CaAx, tangential_drag_area, per_length}
//   buoy: {held_at: [x, z] from the anchor, diameter, weight_in_air,
//          weight_in_water (its buoyancy; default a sphere's), Cd, Ca: 0.5}
//   relax: {...}                   # the hold; keys of a relax step, defaults below
//   dynamic: {dt, steps, ...}      # after the release; keys of a dynamic step
//   summary:, figure:              # default: the buoy's final x and z, its largest speed, the
//                                  # largest anchor tension; a figure of the buoy's x, z, speed
//                                  # and the anchor tension
//
// Node names: the anchor is cable.start (cable.anchor: the line is a mooring line, anchor:
// start), the buoy cable.end (cable.fairlead).
#include <cmath>

#include "apps/case/input/units.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/case/scenarios/scenario.hpp"
#include "apps/case/scenarios/yaml_text.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

struct Hold {
  double x = 0.0, z = 0.0;
};

}  // namespace

YAML::Node expandSinglePointMoor(Diagnostics& diag, const YAML::Node& root) {
  const UnitSystem units = scenarioUnits(root);
  Input in(diag, units);
  Fields top(
      diag, root, "",
      {"name",     "title",  "units",     "scenario",  "water",    "waves",   "current", "seabed",
       "anchor",   "cable",  "buoy",      "gravity",   "relax",    "dynamic", "steps",   "summary",
       "figure",   "output", "histories", "materials", "sections", "nodes",   "lines",   "surfaces",
       "elements", "bodies", "supports",  "loads",     "node_sets"});
  refuseGeneratedKeys(diag, top, "single_point_moor", "anchor:, cable:, buoy:");
  // Water: its density and depth make the rope's buoyancy and the anchor's default place.
  const ScenarioWater water = readScenarioWater(in, top, units);
  const double rho = water.density, depth = water.depth, g = water.gravity;
  Eigen::Vector3d anchor(0.0, 0.0, -depth);
  if (const YAML::Node* n = top.find("anchor"))
    anchor = in.vector3(*n, "anchor", kind::kLength).value_or(anchor);

  // The line.
  const YAML::Node* cable_node = top.require("cable");
  Fields cable(diag, cable_node ? *cable_node : YAML::Node(), "cable",
               {"length", "EA", "weight_in_air", "weight_in_water", "diameter", "elements", "order",
                "Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"});
  const auto need = [&](Fields& f, const char* key, const QuantityKind& kind) {
    const YAML::Node* n = f.require(key);
    return n ? in.quantity(*n, f.path(key), kind, Limit::Positive) : std::nullopt;
  };
  const auto length = need(cable, "length", kind::kLength);
  const auto ea = need(cable, "EA", kind::kForce);
  const QuantityKind weight_per_length{"a force per length", {1, 0, -2}};
  const auto w_air = need(cable, "weight_in_air", weight_per_length);
  const auto d = need(cable, "diameter", kind::kLength);
  const int elements = in.integerOr(cable, "elements", 1, 4);
  const int order = in.integerOr(cable, "order", 2, 3);
  if (order > 4)
    diag.error(cable.keyLine("order"), "cable.order: out of range (got " + std::to_string(order) +
                                           ", expected 2, 3 or 4 nodes an element)");
  const double area = d ? kPi * *d * *d / 4.0 : 0.0;
  if (const YAML::Node* n = cable.find("weight_in_water")) {
    const auto w_water = in.quantity(*n, cable.path("weight_in_water"), weight_per_length);
    if (w_water && w_air && d && rho > 0.0) {
      const double expected = *w_air - rho * g * area;
      if (std::abs(*w_water - expected) > 0.01 * std::abs(*w_air))
        diag.error(*n,
                   "cable.weight_in_water: does not match the buoyancy of the diameter in "
                   "this water (got " +
                       formatNumber(*w_water) + ", expected " + formatNumber(expected) +
                       " = weight_in_air - rho g pi d^2 / 4, within 1% of the weight in "
                       "air)");
    }
  }

  // The buoy.
  const YAML::Node* buoy_node = top.require("buoy");
  Fields buoy(diag, buoy_node ? *buoy_node : YAML::Node(), "buoy",
              {"held_at", "diameter", "weight_in_air", "weight_in_water", "Cd", "Ca"});
  std::optional<Hold> hold;
  if (const YAML::Node* h = buoy.require("held_at")) {
    if (!h->IsSequence() || h->size() != 2) {
      diag.error(*h,
                 "buoy.held_at: expected [x, z] from the anchor (got " + describeNode(*h) + ")");
    } else {
      const auto x = in.quantity((*h)[0], "buoy.held_at.x", kind::kLength);
      const auto z = in.quantity((*h)[1], "buoy.held_at.z", kind::kLength);
      if (x && z) hold = Hold{*x, *z};
    }
  }
  const auto diameter = need(buoy, "diameter", kind::kLength);
  const YAML::Node* weight = buoy.require("weight_in_air");
  const YAML::Node* cd = buoy.require("Cd");
  std::optional<double> volume;
  if (const YAML::Node* n = buoy.find("weight_in_water")) {
    const auto w_water = in.quantity(*n, buoy.path("weight_in_water"), kind::kForce);
    const auto w =
        weight ? in.quantity(*weight, buoy.path("weight_in_air"), kind::kForce, Limit::NonNegative)
               : std::nullopt;
    if (w_water && w && rho > 0.0) {
      if (*w - *w_water <= 0.0)
        diag.error(*n, "buoy.weight_in_water: not below its weight in air (got " +
                           formatNumber(*w_water) + ", expected less than " + formatNumber(*w) +
                           ": the water buoys it up)");
      else
        volume = (*w - *w_water) / (rho * g);
    }
  }
  if (hold && length && std::hypot(hold->x, hold->z) > *length)
    diag.warning(buoy.keyLine("held_at"),
                 "buoy.held_at: " + formatNumber(std::hypot(hold->x, hold->z)) +
                     " from the anchor, further than the line's unstretched length " +
                     formatNumber(*length) + ": the line is stretched while held");
  const YAML::Node* steps = top.find("steps");
  const YAML::Node* dynamic = steps ? top.find("dynamic") : top.require("dynamic");
  checkScenarioStepKeys(diag, top, {"relax", "dynamic"});
  const auto cd_value =
      cd ? in.quantity(*cd, buoy.path("Cd"), kind::kNumber, Limit::NonNegative) : std::nullopt;
  if (!diag.empty() || !length || !ea || !w_air || !d || !hold || !diameter || !weight ||
      !cd_value || !(dynamic || steps))
    return root;

  // The expanded document: the case's own keys, then what the scenario stands for.
  YAML::Node doc(YAML::NodeType::Map);
  for (const auto& key : {"name", "title", "units", "water", "waves", "current", "seabed",
                          "histories", "summary", "figure", "output"})
    if (const YAML::Node* n = top.find(key)) doc[key] = *n;
  doc["materials"]["line"]["type"] = "linear_elastic";
  doc["materials"]["line"]["E"] = scenarioNumber(*ea / area);  // EA over pi d^2 / 4
  YAML::Node section;
  section["material"] = "line";
  section["area"] = scenarioNumber(area);
  section["density"] = scenarioNumber(*w_air / (g * area));  // mass per length over the area
  YAML::Node hydro;
  hydro["diameter"] = *cable.find("diameter");
  for (const char* key : {"Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"})
    if (const YAML::Node* n = cable.find(key)) hydro[key] = *n;
  section["hydro"] = hydro;
  doc["sections"]["line"] = section;
  YAML::Node line;
  line["name"] = "cable";
  line["from"] = flowSequence(
      {scenarioNumber(anchor.x()), scenarioNumber(anchor.y()), scenarioNumber(anchor.z())});
  line["to"] = flowSequence({scenarioNumber(anchor.x() + *length), scenarioNumber(anchor.y()),
                             scenarioNumber(anchor.z())});
  line["elements"] = elements;
  line["order"] = order;
  line["section"] = "line";
  line["anchor"] = "start";  // cable.anchor; its fairlead, cable.end, holds the buoy
  doc["lines"].push_back(line);
  YAML::Node body;
  body["node"] = "cable.end";
  body["Cd"] = *cd;
  if (volume) {  // the stated weights in water and air make its buoyancy
    body["type"] = "point";
    body["volume"] = scenarioNumber(*volume);
    body["drag_area"] = scenarioNumber(*cd_value * kPi * *diameter * *diameter / 4.0);
    body.remove("Cd");
  } else {
    body["type"] = "sphere";
    body["diameter"] = *buoy.find("diameter");
  }
  body["Ca"] = buoy.find("Ca") ? *buoy.find("Ca") : YAML::Node("0.5");
  body["weight"] = *weight;
  doc["bodies"].push_back(body);
  YAML::Node planar, fixed_anchor, held;
  planar["nodes"] = "all";
  planar["fix"] = flowSequence({"y"});
  fixed_anchor["node"] = "cable.start";
  fixed_anchor["fix"] = flowSequence({"x", "z"});
  held["node"] = "cable.end";
  held["fix"] = flowSequence({"x", "z"});
  held["displacement"] = flowSequence({scenarioNumber(hold->x - *length), scenarioNumber(hold->z)});
  for (const YAML::Node& s : {planar, fixed_anchor, held}) doc["supports"].push_back(s);
  doc["loads"]["gravity"]["g"] = scenarioNumber(g);
  // Unless the case says otherwise: where the buoy ends, how fast it went, how hard the anchor
  // was pulled, and a figure of the four over time.
  if (!top.find("summary")) {
    const auto quantity = [](const char* q, const char* stat) {
      YAML::Node n;
      n["quantity"] = q;
      if (std::string(q) == "end_tension") {
        n["line"] = "cable";
        n["end"] = "anchor";
      } else {
        n["node"] = "cable.end";
      }
      if (stat) n["stat"] = stat;
      return n;
    };
    doc["summary"]["buoy_x"] = quantity("position_x", nullptr);
    doc["summary"]["buoy_z"] = quantity("position_z", nullptr);
    doc["summary"]["buoy_speed_max"] = quantity("speed", "max");
    doc["summary"]["anchor_tension_max"] = quantity("end_tension", "max");
  }
  if (!top.find("figure")) {
    std::vector<YAML::Node> series;
    for (const char* q : {"position_x", "position_z", "speed"})
      series.push_back(nodeSeries(q, YAML::Node("cable.end")));
    YAML::Node anchor_tension;
    anchor_tension["quantity"] = "tension_end";
    anchor_tension["line"] = "cable";
    anchor_tension["end"] = "anchor";
    series.push_back(anchor_tension);
    if (const YAML::Node figure = defaultFigure(top, series); figure.IsMap())
      doc["figure"] = figure;
  }
  if (steps) {
    doc["steps"] = *steps;
  } else {
    // The hold: viscous relaxation (Appendix C) from the straight line, with a damping constant
    // of a hundredth of the line's axial stiffness EA / L, reduced by each step's change.
    YAML::Node relax;
    relax["name"] = "held";
    relax["tolerance"] = "1e-6";
    relax["damping"] = scenarioNumber(0.01 * *ea / *length);
    relax["initial_damping_factor"] = "0.01";
    if (const YAML::Node* r = top.find("relax"))
      for (const auto& kv : *r) relax[kv.first.Scalar()] = kv.second;
    // The case's own map, so that its place in the file names the step in messages.
    YAML::Node released = *dynamic;
    released["name"] = "released";
    YAML::Node let_go;
    let_go["node"] = "cable.end";
    let_go["dofs"] = flowSequence({"x", "z"});
    released["release"].push_back(let_go);
    YAML::Node relax_step, dynamic_step;
    relax_step["relax"] = relax;
    dynamic_step["dynamic"] = released;
    doc["steps"].push_back(relax_step);
    doc["steps"].push_back(dynamic_step);
  }
  return doc;
}

}  // namespace flexmoor::app
