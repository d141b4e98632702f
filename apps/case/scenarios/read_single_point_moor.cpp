// scenario: single_point_moor in a case file: its own keys read into a SinglePointMoorSpec
// (single_point_moor.hpp has the model), on which the reader reads the case's other sections.
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
//   steps:, summary:, figure:, histories:, waves:, current:, seabed:, output:   # the case's own
//
// Node names: the anchor is cable.start (cable.anchor: the line is a mooring line, anchor:
// start), the buoy cable.end (cable.fairlead).
#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/case/input/units.hpp"
#include "apps/case/scenarios/scenario_keys.hpp"
#include "apps/case/scenarios/scenario_model.hpp"
#include "apps/case/scenarios/single_point_moor.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

struct Hold {
  double x = 0.0, z = 0.0;
};

}  // namespace

const std::vector<std::string>& singlePointMoorKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = {"name",    "title",   "units",  "scenario", "water",
                                  "waves",   "current", "seabed", "anchor",   "cable",
                                  "buoy",    "gravity", "relax",  "dynamic",  "steps",
                                  "summary", "figure",  "output", "histories"};
    k.insert(k.end(), scenarioGeneratedKeys().begin(), scenarioGeneratedKeys().end());
    return k;
  }();
  return keys;
}

std::optional<ScenarioModel> readSinglePointMoor(CaseBuilder& b, Fields& top) {
  Diagnostics& diag = b.diag;
  Input& in = b.in;
  refuseGeneratedKeys(diag, top, "single_point_moor", "anchor:, cable:, buoy:");
  // Water: its density and depth make the rope's buoyancy and the anchor's default place.
  const ScenarioWater water = readScenarioWater(in, top, in.units);
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
  std::optional<LineHydroSpec> hydro;
  if (d) hydro = readLineHydro(b, cable);
  const auto ca = in.quantityOr(buoy, "Ca", kind::kNumber, Limit::NonNegative, 0.5);
  const auto buoy_weight =
      weight ? in.quantity(*weight, buoy.path("weight_in_air"), kind::kForce, Limit::NonNegative)
             : std::nullopt;
  if (!diag.empty() || !length || !ea || !w_air || !d || !hold || !diameter || !weight ||
      !cd_value || !(dynamic || steps) || !hydro || !buoy_weight)
    return std::nullopt;

  SinglePointMoorSpec spec;
  spec.units = in.units;
  spec.water = {rho, depth, g};
  spec.anchor = anchor;
  spec.length = *length;
  spec.ea = *ea;
  spec.weight_in_air = *w_air;
  spec.hydro = *hydro;
  spec.elements = elements;
  spec.order = order;
  spec.held_x = hold->x;
  spec.held_z = hold->z;
  const double drag = cd_value.value(), buoy_diameter = diameter.value();
  if (volume)  // the stated weights in water and air make its buoyancy
    spec.buoy =
        hydro::PointBody{*volume, drag * kPi * buoy_diameter * buoy_diameter / 4.0, ca, 0.0};
  else
    spec.buoy = hydro::PointBody::sphere(buoy_diameter, drag, ca);
  spec.buoy_mass = *buoy_weight / g;
  ScenarioModel model;
  model.spec = singlePointMoor(spec, {});
  const int buoy_at = model.spec.lines.front().nodes.back();
  model.steps = {{"relax", singlePointMoorHold(spec), true},
                 {"dynamic", singlePointMoorRelease(buoy_at), true}};
  const int cable_line = top.keyLine("cable"), buoy_line = top.keyLine("buoy");
  model.origins =
      ModelOrigins::sourceless(model.spec.mesh.nodeCount(), model.spec.mesh.elementCount());
  for (int e = 0; e < model.spec.mesh.elementCount(); ++e)
    model.origins.elements[e] = model.spec.mesh.elements[e].kind == ElementSpec::Kind::PointMass
                                    ? ElementOrigin{buoy_line, "buoy", ""}
                                    : ElementOrigin{cable_line, "cable", "cable"};
  model.origins.node_lines.assign(model.spec.mesh.nodeCount(), cable_line);
  model.spec.ocean.bodies.front().line = buoy_line;
  model.summary = singlePointMoorSummary;
  return model;
}

}  // namespace flexmoor::app
