// scenario: submerged_tube: a fluid-filled membrane tube with a horizontal axis (along y), one
// layer of Q8 elements between symmetry planes, held under water by a pair of mooring cables
// from the layer's middle to anchors on the bed, under waves; relaxed to equilibrium, modes, then
// a dynamic step. The dissertation's Example 9 is one (cases/seed/ex9-submerged-tube.yaml is
// the same model written out).
//
//   scenario: submerged_tube
//   water: {density, depth}             # required; waves: copied as they are
//   gravity: 32.174 ft/s^2              # default: standard
//   tube: {diameter, axis_depth, layer, thickness, E, nu, density, elements: 6}
//   liquid: {specific_gravity (or density), resultant}   # resultant: liquid minus sea pressure
//                                                         # at the axis, static
//   mooring: {attach_angle, angle, area, E, density, elements: 3, order: 3, diameter, Cn, Ct, Ca,
//             CaAx, tangential_drag_area, per_length}
//     # attached at 180 deg +- attach_angle from the top (a multiple of 180 deg / elements, so an
//     # element corner is there), running `angle` from the vertical outwards down to the bed
//   relax: {...}, modes: {count: 6, ...}, dynamic: {...}   # the steps' keys (dynamic required)
//   summary:, figure:                   # default: periods 1-6, node 1's largest x, node 7's
//                                       # largest z, the largest mooring tension; a figure of
//                                       # nodes 1, 7, 4, 10 and the first cable's tension
//
// Node names: the cables are mooring lines mooring_right and mooring_left (anchor: end: their .end,
// .anchor, on the bed; their .start, .fairlead, at the tube), the
// membrane the surface tube; nodes 1, 4, 7, 10 of the dissertation (top, right, bottom, left on
// the ring y = 0) by position.
#include <cmath>

#include "apps/case/input/units.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/case/scenarios/scenario.hpp"
#include "apps/case/scenarios/yaml_text.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

YAML::Node point(double x, double y, double z) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (double v : {x, y, z}) n.push_back(scenarioNumber(v));
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

YAML::Node at(double x, double y, double z) {
  YAML::Node n;
  n["at"] = point(x, y, z);
  return n;
}

}  // namespace

YAML::Node expandSubmergedTube(Diagnostics& diag, const YAML::Node& root) {
  const UnitSystem units = scenarioUnits(root);
  Input in(diag, units);
  std::vector<std::string> allowed = {"name",    "title", "units",   "scenario", "water", "waves",
                                      "gravity", "tube",  "liquid",  "mooring",  "relax", "modes",
                                      "dynamic", "steps", "summary", "figure",   "output"};
  allowed.insert(allowed.end(), scenarioGeneratedKeys().begin(), scenarioGeneratedKeys().end());
  Fields top(diag, root, "", allowed);
  refuseGeneratedKeys(diag, top, "submerged_tube", "tube:, liquid:, mooring:");
  const ScenarioWater water = readScenarioWater(in, top, units);
  const double rho = water.density, depth = water.depth, g = water.gravity;
  const auto need = [&](Fields& f, const char* key, const QuantityKind& kind) {
    const YAML::Node* n = f.require(key);
    return n ? in.quantity(*n, f.path(key), kind, Limit::Positive) : std::nullopt;
  };

  const YAML::Node* tube_node = top.require("tube");
  Fields tube(diag, tube_node ? *tube_node : YAML::Node(), "tube",
              {"diameter", "axis_depth", "layer", "thickness", "E", "nu", "density", "elements"});
  const auto diameter = need(tube, "diameter", kind::kLength);
  const auto axis_depth = need(tube, "axis_depth", kind::kLength);
  const auto layer = need(tube, "layer", kind::kLength);
  for (const char* key : {"thickness", "E", "nu", "density"}) tube.require(key);
  const int around = in.integerOr(tube, "elements", 3, 6);

  const YAML::Node* liquid_node = top.require("liquid");
  Fields liquid(diag, liquid_node ? *liquid_node : YAML::Node(), "liquid",
                {"specific_gravity", "density", "resultant"});
  const auto resultant = [&]() -> std::optional<double> {
    const YAML::Node* n = liquid.require("resultant");
    return n ? in.quantity(*n, liquid.path("resultant"), kind::kPressure) : std::nullopt;
  }();

  const YAML::Node* mooring_node = top.require("mooring");
  Fields mooring(diag, mooring_node ? *mooring_node : YAML::Node(), "mooring",
                 {"attach_angle", "angle", "area", "E", "density", "elements", "order", "diameter",
                  "Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"});
  const auto attach = need(mooring, "attach_angle", kind::kNumber);
  const auto angle = need(mooring, "angle", kind::kNumber);
  for (const char* key : {"density", "diameter", "Cn", "Ca"}) mooring.require(key);
  const auto area = need(mooring, "area", kind::kArea);
  const auto youngs = need(mooring, "E", kind::kPressure);
  const int elements = in.integerOr(mooring, "elements", 1, 3);
  const int order = in.integerOr(mooring, "order", 2, 3);
  // The attachment must be an element corner: the mesh starts at 180 deg - attach_angle.
  const double pitch = kPi / around;
  if (attach && std::abs(*attach / pitch - std::round(*attach / pitch)) > 1e-9)
    diag.error(mooring.keyLine("attach_angle"),
               "mooring.attach_angle: not at an element corner (got " +
                   formatNumber(*attach * 180.0 / kPi) + " deg, expected a multiple of 180 deg / " +
                   std::to_string(around) + " = " + formatNumber(180.0 / around) + " deg)");
  if (angle && !(*angle < kPi / 2.0))
    diag.error(mooring.keyLine("angle"), "mooring.angle: the cable would not reach the bed (got " +
                                             formatNumber(*angle * 180.0 / kPi) +
                                             " deg from the vertical, expected less "
                                             "than 90 deg)");
  const YAML::Node* steps = top.find("steps");
  const YAML::Node* dynamic = steps ? top.find("dynamic") : top.require("dynamic");
  if (!diag.empty() || !diameter || !axis_depth || !layer || !resultant || !attach || !angle ||
      !area || !youngs || !(dynamic || steps) || !(rho > 0.0) || !(depth > 0.0))
    return root;
  const double R = *diameter / 2.0, zc = -*axis_depth;
  const double za = zc - R * std::cos(*attach), xa = R * std::sin(*attach);
  if (za <= -depth) {
    diag.error(tube.keyLine("axis_depth"),
               "tube.axis_depth: the mooring's attachment is at or below the bed (got z = " +
                   formatNumber(za) + ", expected above -" + formatNumber(depth) + ")");
    return root;
  }
  const double run = (za + depth) * std::tan(*angle);

  YAML::Node doc(YAML::NodeType::Map);
  for (const auto& key :
       {"name", "title", "units", "water", "waves", "summary", "figure", "output"})
    if (const YAML::Node* n = top.find(key)) doc[key] = *n;
  doc["materials"]["skin"]["type"] = "linear_elastic";
  doc["materials"]["skin"]["E"] = *tube.find("E");
  doc["materials"]["skin"]["nu"] = *tube.find("nu");
  doc["materials"]["rope"]["type"] = "linear_elastic";
  doc["materials"]["rope"]["E"] = *mooring.find("E");
  doc["sections"]["wall"]["material"] = "skin";
  doc["sections"]["wall"]["thickness"] = *tube.find("thickness");
  doc["sections"]["wall"]["density"] = *tube.find("density");
  YAML::Node section, hydro;
  section["material"] = "rope";
  section["area"] = *mooring.find("area");
  section["density"] = *mooring.find("density");
  for (const char* key :
       {"diameter", "Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"})
    if (const YAML::Node* n = mooring.find(key)) hydro[key] = *n;
  section["hydro"] = hydro;
  doc["sections"]["mooring"] = section;
  for (const double side : {1.0, -1.0}) {
    YAML::Node line;
    line["name"] = side > 0.0 ? "mooring_right" : "mooring_left";
    line["from"] = point(side * xa, *layer / 2.0, za);
    line["to"] = point(side * (xa + run), *layer / 2.0, -depth);
    line["elements"] = elements;
    line["order"] = order;
    line["section"] = "mooring";
    line["anchor"] = "end";  // on the bed: mooring_right.anchor, its fairlead at the tube
    doc["lines"].push_back(line);
  }
  YAML::Node surface;
  surface["name"] = "tube";
  surface["shape"] = "cylinder";
  surface["axis"] = "y";
  surface["centre"] = point(0.0, 0.0, zc);
  surface["radius"] = scenarioNumber(R);
  surface["length"] = scenarioNumber(*layer);
  YAML::Node angles(YAML::NodeType::Sequence);  // radians, a corner at 180 deg - attach_angle
  angles.push_back(scenarioNumber(kPi - *attach));
  angles.push_back(scenarioNumber(3.0 * kPi - *attach));
  angles.SetStyle(YAML::EmitterStyle::Flow);
  surface["angles"] = angles;
  YAML::Node divisions(YAML::NodeType::Sequence);
  divisions.push_back(around);
  divisions.push_back(1);
  surface["divisions"] = divisions;
  surface["element"] = "Q8";
  surface["section"] = "wall";
  doc["surfaces"].push_back(surface);
  YAML::Node symmetry, anchors;
  symmetry["nodes"] = "all";
  symmetry["fix"].push_back("y");
  anchors["nodes"].push_back("mooring_right.end");
  anchors["nodes"].push_back("mooring_left.end");
  anchors["fix"].push_back("x");
  anchors["fix"].push_back("z");
  doc["supports"].push_back(symmetry);
  doc["supports"].push_back(anchors);
  doc["loads"]["gravity"]["g"] = scenarioNumber(g);
  YAML::Node sea, fluid;
  sea["on"] = "tube";
  sea["water_side"] = "positive";
  doc["loads"]["wave_pressure"].push_back(sea);
  fluid["on"] = "tube";
  for (const char* key : {"specific_gravity", "density"})
    if (const YAML::Node* n = liquid.find(key)) fluid[key] = *n;
  fluid["pressure"] =
      scenarioNumber(*resultant + rho * g * *axis_depth);  // sea's at the axis + resultant
  fluid["at_z"] = scenarioNumber(zc);
  doc["loads"]["enclosed_fluid"].push_back(fluid);

  if (!top.find("summary")) {
    for (int k = 1; k <= 6 && k <= 3 * around; ++k) {
      YAML::Node p;
      p["quantity"] = "period";
      p["mode"] = k;
      p["step"] = "modes";
      doc["summary"]["period_" + std::to_string(k)] = p;
    }
    YAML::Node x1, z7, t;
    x1["quantity"] = "displacement_x";
    x1["node"] = at(0.0, 0.0, zc + R);
    x1["stat"] = "max";
    z7["quantity"] = "displacement_z";
    z7["node"] = at(0.0, 0.0, zc - R);
    z7["stat"] = "max";
    t["quantity"] = "max_tension";
    t["stat"] = "max";
    doc["summary"]["node1_x_max"] = x1;
    doc["summary"]["node7_z_max"] = z7;
    doc["summary"]["mooring_tension_max"] = t;
  }
  if (!top.find("figure")) {
    const double ring[4][2] = {{0.0, zc + R}, {0.0, zc - R}, {R, zc}, {-R, zc}};
    std::vector<YAML::Node> series;
    for (const auto& p : ring)
      for (const char* q : {"displacement_x", "displacement_z"})
        series.push_back(nodeSeries(q, at(p[0], 0.0, p[1])));
    series.push_back(firstElementTensionSeries());
    if (const YAML::Node figure = defaultFigure(top, series); figure.IsMap())
      doc["figure"] = figure;
  }
  if (steps) {
    doc["steps"] = *steps;
    return doc;
  }
  // Equilibrium by viscous relaxation (Newton from the unstressed membrane has a singular
  // tangent: its ovalling is free), with a damping constant of about twice a cable's axial
  // stiffness EA / l, rounded to a power of ten.
  YAML::Node relax, modes, waves = *dynamic;
  relax["name"] = "equilibrium";
  relax["tolerance"] = "1e-6";
  const double length = std::hypot(run, za + depth);
  relax["damping"] =
      scenarioNumber(std::pow(10.0, std::round(std::log10(2.0 * *youngs * *area / length))));
  if (const YAML::Node* r = top.find("relax"))
    for (const auto& kv : *r) relax[kv.first.Scalar()] = kv.second;
  modes["name"] = "modes";
  modes["count"] = 6;
  if (const YAML::Node* m = top.find("modes"))
    for (const auto& kv : *m) modes[kv.first.Scalar()] = kv.second;
  waves["name"] = "waves";
  YAML::Node s1, s2, s3;
  s1["relax"] = relax;
  s2["modes"] = modes;
  s3["dynamic"] = waves;
  for (const YAML::Node& s : {s1, s2, s3}) doc["steps"].push_back(s);
  return doc;
}

}  // namespace flexmoor::app
