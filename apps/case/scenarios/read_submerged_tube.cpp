// scenario: submerged_tube in a case file: its own keys read into a SubmergedTubeSpec
// (submerged_tube.hpp has the model), on which the reader reads the case's other sections.
//
//   scenario: submerged_tube
//   water: {density, depth}             # required; waves: as in any case
//   gravity: 32.174 ft/s^2              # default: standard
//   tube: {diameter, axis_depth, layer, thickness, E, nu, density, elements: 6}
//   liquid: {specific_gravity (or density), resultant}   # resultant: liquid minus sea pressure
//                                                         # at the axis, static
//   mooring: {attach_angle, angle, area, E, density, elements: 3, order: 3, diameter, Cn, Ct, Ca,
//             CaAx, tangential_drag_area, per_length}
//     # attached at 180 deg +- attach_angle from the top (a multiple of 180 deg / elements, so an
//     # element corner is there), running `angle` from the vertical outwards down to the bed
//   relax: {...}, modes: {count: 6, ...}, dynamic: {...}   # the steps' keys (dynamic required)
//   steps:, summary:, figure:, output:  # the case's own
//
// Node names: the cables are mooring lines mooring_right and mooring_left, the membrane the
// surface tube; nodes 1, 4, 7, 10 of the dissertation (top, right, bottom, left on the ring
// y = 0) by position.
#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/case/input/physical_range.hpp"
#include "apps/case/input/units.hpp"
#include "apps/case/scenarios/scenario_keys.hpp"
#include "apps/case/scenarios/scenario_model.hpp"
#include "apps/case/scenarios/submerged_tube.hpp"
#include "apps/common/format_number.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/material/membrane_material.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

}  // namespace

const std::vector<std::string>& submergedTubeKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k = {"name",    "title", "units",   "scenario", "water", "waves",
                                  "gravity", "tube",  "liquid",  "mooring",  "relax", "modes",
                                  "dynamic", "steps", "summary", "figure",   "output"};
    k.insert(k.end(), scenarioGeneratedKeys().begin(), scenarioGeneratedKeys().end());
    return k;
  }();
  return keys;
}

std::optional<ScenarioModel> readSubmergedTube(CaseBuilder& b, Fields& top) {
  Diagnostics& diag = b.diag;
  Input& in = b.in;
  const auto need = [&](Fields& f, const char* key, const QuantityKind& kind) {
    const YAML::Node* n = f.require(key);
    return n ? in.quantity(*n, f.path(key), kind, Limit::Positive) : std::nullopt;
  };
  // A section's density: required, at least 0 and physically plausible.
  const auto density = [&](Fields& f) -> std::optional<double> {
    const YAML::Node* n = f.require("density");
    const auto d =
        n ? in.quantity(*n, f.path("density"), kind::kDensity, Limit::NonNegative) : std::nullopt;
    if (d && !inPhysicalRange(in, *n, f.path("density"), *d, kSectionDensityRange))
      return std::nullopt;
    return d;
  };
  refuseGeneratedKeys(diag, top, "submerged_tube", "tube:, liquid:, mooring:");
  const ScenarioWater water = readScenarioWater(in, top, in.units);
  const double rho = water.density, depth = water.depth, g = water.gravity;

  const YAML::Node* tube_node = top.require("tube");
  Fields tube(diag, tube_node ? *tube_node : YAML::Node(), "tube",
              {"diameter", "axis_depth", "layer", "thickness", "E", "nu", "density", "elements"});
  const auto diameter = need(tube, "diameter", kind::kLength);
  const auto axis_depth = need(tube, "axis_depth", kind::kLength);
  const auto layer = need(tube, "layer", kind::kLength);
  const auto thickness = need(tube, "thickness", kind::kLength);
  const auto tube_e = need(tube, "E", kind::kPressure);
  const auto tube_density = density(tube);
  std::optional<double> nu;
  if (const YAML::Node* n = tube.require("nu")) {
    nu = in.quantity(*n, tube.path("nu"), kind::kNumber);
    if (nu && !(*nu > -1.0 && *nu < 0.5 + 1e-12)) {
      diag.error(*n, tube.path("nu") + ": out of range (got " + n->Scalar() +
                         ", expected a Poisson ratio above -1 and at most 0.5)");
      nu.reset();
    }
  }
  const int around = in.integerOr(tube, "elements", 3, 6);

  const YAML::Node* liquid_node = top.require("liquid");
  Fields liquid(diag, liquid_node ? *liquid_node : YAML::Node(), "liquid",
                {"specific_gravity", "density", "resultant"});
  const YAML::Node* liquid_density = liquid.find("density");
  const YAML::Node* sg = liquid.find("specific_gravity");
  std::optional<double> fluid_density;
  if (liquid_density && sg)
    diag.error(*sg, "liquid: give either density or specific_gravity, not both");
  else if (!liquid_density && !sg && liquid_node)
    diag.error(*liquid_node,
               "liquid: needs the liquid's density (got neither density nor "
               "specific_gravity, expected one of them)");
  else if (liquid_density)
    fluid_density =
        in.quantity(*liquid_density, liquid.path("density"), kind::kDensity, Limit::Positive);
  else if (sg)
    if (const auto ratio =
            in.quantity(*sg, liquid.path("specific_gravity"), kind::kNumber, Limit::Positive))
      fluid_density = *ratio * rho;
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
  const auto rope_density = density(mooring);
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
  const std::optional<LineHydroSpec> hydro = readLineHydro(b, mooring);
  if (!diag.empty() || !diameter || !axis_depth || !layer || !resultant || !attach || !angle ||
      !area || !youngs || !(dynamic || steps) || !(rho > 0.0) || !(depth > 0.0) || !thickness ||
      !tube_e || !tube_density || !nu || !fluid_density || !rope_density || !hydro)
    return std::nullopt;
  // The attachment, R cos(attach_angle) below the axis, above the bed.
  const double za = -*axis_depth - *diameter / 2.0 * std::cos(*attach);
  if (za <= -depth) {
    diag.error(tube.keyLine("axis_depth"),
               "tube.axis_depth: the mooring's attachment is at or below the bed (got z = " +
                   formatNumber(za) + ", expected above -" + formatNumber(depth) + ")");
    return std::nullopt;
  }

  SubmergedTubeSpec spec;
  spec.units = in.units;
  spec.water = {rho, depth, g};
  spec.diameter = *diameter;
  spec.axis_depth = *axis_depth;
  spec.layer = *layer;
  spec.wall.thickness = *thickness;
  spec.wall.density = *tube_density;
  spec.wall.material = std::make_shared<material::LinearElasticPlaneStress>(*tube_e, *nu);
  spec.around = around;
  spec.liquid_density = *fluid_density;
  spec.resultant = *resultant;
  spec.attach_angle = *attach;
  spec.angle = *angle;
  spec.rope.area = *area;
  spec.rope.density = *rope_density;
  spec.rope.material =
      std::make_shared<material::LinearElasticCable>(*youngs, material::Compression::TensionOnly);
  spec.hydro = *hydro;
  spec.elements = elements;
  spec.order = order;
  ScenarioModel model;
  model.spec = submergedTube(spec, {});
  StepSpec waves;
  waves.kind = StepSpec::Kind::Dynamic;
  waves.name = "waves";
  model.steps = {{"relax", submergedTubeEquilibrium(spec), true},
                 {"modes", submergedTubeModes(), true},
                 {"dynamic", waves, true}};
  model.summary = [spec](const CaseSpec& c) { return submergedTubeSummary(c, spec); };
  const int tube_line = top.keyLine("tube"), mooring_line = top.keyLine("mooring");
  const CaseSpec& c = model.spec;
  model.origins = ModelOrigins::sourceless(c.mesh.nodeCount(), c.mesh.elementCount());
  for (const CaseLine& line : c.lines)
    for (const int e : line.elements)
      model.origins.elements[e] = {mooring_line, "mooring", "mooring"};
  for (const int e : c.element_sets.at("tube"))
    model.origins.elements[e] = {tube_line, "tube", "wall"};
  model.origins.node_lines.assign(c.mesh.nodeCount(), tube_line);
  for (const CaseLine& line : c.lines)
    for (const int n : line.nodes) model.origins.node_lines[n] = mooring_line;
  model.spec.enclosed_fluids.front().line = top.keyLine("liquid");
  return model;
}

}  // namespace flexmoor::app
