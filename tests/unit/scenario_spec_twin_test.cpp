// A scenario stated in code through its function and the same scenario read from its case file
// give the same model and the same results, to the bit: single_point_moor (singlePointMoor),
// Example 8's case, and submerged_tube (submergedTube), Example 9's, with their values in the
// case's units written to 17 digits.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "apps/case/build/build_case.hpp"
#include "apps/case/case_reader.hpp"
#include "apps/case/scenarios/single_point_moor.hpp"
#include "apps/case/scenarios/submerged_tube.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/twin_runs.hpp"

namespace flexmoor::test {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

void expectSameRun(const app::Case& file, const app::Case& code) {
  expectSameModel(*file.model, *code.model);
  EXPECT_EQ(file.lines, code.lines);
  RecordedRun a, b;
  runRecorded(file, a);
  runRecorded(code, b);
  expectSameRecords(a, b);
  ASSERT_GT(b.records.frames().size(), 2u);
  expectSameSummary(a, b);
  EXPECT_FALSE(b.result.summary.empty());
  ASSERT_TRUE(code.figure.has_value());
  EXPECT_EQ(file.figure->series, code.figure->series);
}

// Example 8 in US units (ft, slug, s, lbf): the line 71.56 in, EA 4.8 lbf, 11.443e-3 lbf/ft in
// air, 0.163 in across; the buoy held at (50 in, 50 in), 2 in across, 0.025 lbf in air and
// -0.121 lbf in water, Cd 0.5; released for 200 steps of 0.005 s.
app::SinglePointMoorSpec example8() {
  app::SinglePointMoorSpec spec;
  spec.units = app::UnitSystem::US;
  const double g = 32.174, rho = 1.94364, depth = 80.0 / 12.0;
  spec.water = {rho, depth, g};
  spec.anchor = Eigen::Vector3d(0.0, 0.0, -depth);
  spec.length = 71.56 / 12.0;
  spec.ea = 4.8;
  spec.weight_in_air = 11.443e-3;
  spec.hydro.coefficients = {
      0.163 / 12.0, 1.2, 0.02, 1.0, 0.0, hydro::MorisonCoefficients::TangentialDragArea::Diameter};
  spec.held_x = 50.0 / 12.0;
  spec.held_z = 50.0 / 12.0;
  const double d = 2.0 / 12.0;
  spec.buoy = hydro::PointBody{(0.025 + 0.121) / (rho * g), 0.5 * M_PI * d * d / 4.0, 0.5, 0.0};
  spec.buoy_mass = 0.025 / g;
  return spec;
}

std::string example8File(const app::SinglePointMoorSpec& s) {
  const double d = s.hydro.coefficients.diameter;
  return "units: US\nscenario: single_point_moor\n"
         "water: {density: " +
         number(s.water.density) + ", depth: " + number(s.water.depth) +
         "}\ngravity: " + number(s.water.gravity) + "\ncable: {length: " + number(s.length) +
         ", EA: " + number(s.ea) + ", weight_in_air: " + number(s.weight_in_air) +
         ", diameter: " + number(d) +
         ", elements: 4, order: 3, Cn: 1.2, Ct: 0.02, Ca: 1.0, tangential_drag_area: diameter}\n"
         "buoy: {held_at: [" +
         number(s.held_x) + ", " + number(s.held_z) + "], diameter: " + number(2.0 / 12.0) +
         ", weight_in_air: 0.025, weight_in_water: -0.121, Cd: 0.5, Ca: 0.5}\n"
         "dynamic: {dt: 0.005, steps: 200, newton: modified, stiffness_update: 2, tolerance: "
         "1e-3}\n";
}

TEST(ScenarioSpecTwin, SinglePointMoorInCodeIsItsCaseFileToTheBit) {
  const app::SinglePointMoorSpec spec = example8();
  const app::Case file = app::readCase(writeCase("ex8-twin.yaml", example8File(spec)));
  app::StepSpec release = app::singlePointMoorRelease(8);  // the buoy: the cable's 9th node
  release.dynamic.schedule = {{0.005, 200}};
  release.dynamic.flavour = solve::NewtonFlavour::Modified;
  release.dynamic.stiffness_update = 2;
  release.dynamic.convergence.displacement_tolerance = 1e-3;
  const app::Case code =
      app::buildCase(app::singlePointMoor(spec, {app::singlePointMoorHold(spec), release}));
  EXPECT_EQ(code.lines.at("cable").back(), 8);
  expectSameRun(file, code);
}

// Example 9 in US units: the tube 10 ft across, its axis 45 ft down in 60 ft of water, a layer
// of 0.5 ft of 6 Q8 elements, its wall 0.25 in of E = 500,000 psi, nu 0.3, 1.5228 slug/ft^3; the
// liquid of specific gravity 0.9 at 5 psi over the sea at the axis; the cables of 0.06545 in^2,
// E = 100,000 psi, 4.6584 slug/ft^3, 0.28868 in across, attached 30 deg from the bottom and
// running 45 deg from the vertical; a regular wave 5 ft high, 5 s long.
app::SubmergedTubeSpec example9() {
  app::SubmergedTubeSpec spec;
  spec.units = app::UnitSystem::US;
  spec.water = {1.99, 60.0, 32.174};
  spec.diameter = 10.0;
  spec.axis_depth = 45.0;
  spec.layer = 0.5;
  spec.wall.thickness = 0.25 / 12.0;
  spec.wall.density = 1.5228;
  spec.wall.material = std::make_shared<material::LinearElasticPlaneStress>(500000.0 * 144.0, 0.3);
  spec.liquid_density = 0.9 * 1.99;
  spec.resultant = 5.0 * 144.0;
  spec.attach_angle = M_PI / 6.0;
  spec.angle = M_PI / 4.0;
  spec.rope.area = 0.06545 / 144.0;
  spec.rope.density = 4.6584;
  spec.rope.material = std::make_shared<material::LinearElasticCable>(
      100000.0 * 144.0, material::Compression::TensionOnly);
  spec.hydro.coefficients = {0.28868 / 12.0,
                             1.2,
                             0.02,
                             1.0,
                             0.0,
                             hydro::MorisonCoefficients::TangentialDragArea::Diameter};
  return spec;
}

std::string example9File(const app::SubmergedTubeSpec& s) {
  const auto& wall = s.wall;
  return "units: US\nscenario: submerged_tube\nwater: {density: 1.99, depth: 60}\n"
         "waves: {components: [{height: 5, period: 5}]}\ngravity: 32.174\n"
         "tube: {diameter: 10, axis_depth: 45, layer: 0.5, thickness: " +
         number(wall.thickness) + ", E: " + number(500000.0 * 144.0) +
         ", nu: 0.3, density: 1.5228, elements: 6}\n"
         "liquid: {specific_gravity: 0.9, resultant: " +
         number(s.resultant) +
         "}\n"
         "mooring: {attach_angle: " +
         number(s.attach_angle) + ", angle: " + number(s.angle) + ", area: " + number(s.rope.area) +
         ", E: " + number(100000.0 * 144.0) +
         ", density: 4.6584, elements: 3, order: 3, diameter: " +
         number(s.hydro.coefficients.diameter) +
         ", Cn: 1.2, Ct: 0.02, Ca: 1.0, CaAx: 0.0, tangential_drag_area: diameter}\n"
         "dynamic: {dt: 0.02, steps: 25, pressure_stiffness: true}\n";
}

TEST(ScenarioSpecTwin, SubmergedTubeInCodeIsItsCaseFileToTheBit) {
  const app::SubmergedTubeSpec spec = example9();
  const app::Case file = app::readCase(writeCase("ex9-twin.yaml", example9File(spec)));
  app::StepSpec waves;
  waves.kind = app::StepSpec::Kind::Dynamic;
  waves.name = "waves";
  waves.dynamic.schedule = {{0.02, 25}};
  waves.dynamic.pressure_load_stiffness = true;
  app::CaseSpec code_spec = app::submergedTube(
      spec, {app::submergedTubeEquilibrium(spec), app::submergedTubeModes(), waves});
  code_spec.ocean.waves.push_back({5.0, 5.0, 0.0, 0.0, 0});
  const app::Case code = app::buildCase(code_spec);
  EXPECT_EQ(file.element_sets, code.element_sets);
  EXPECT_EQ(code.element_sets.at("tube").size(), 6u);
  expectSameRun(file, code);
}

}  // namespace
}  // namespace flexmoor::test
