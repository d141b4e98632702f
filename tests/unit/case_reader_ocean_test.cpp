// The ocean sections of a case file (read_hydro.cpp, build_hydro.cpp): every value is converted
// into the case's system, the defaults of libhydro (SI) too, and the case is built into a sea and
// loads on the model that a run then carries. References are the inputs themselves, converted by
// hand with the exact factors (1 ft = 0.3048 m, 1 lbf = 4.4482216152605 N) or summed by hand;
// tolerances are stated at each check.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/case/case_reader.hpp"
#include "libhydro/loads/body_node_load.hpp"
#include "libhydro/loads/wave_pressure_load.hpp"
#include "libhydro/seabed/seabed_node_load.hpp"
#include "libhydro/seabed/seabed_line_load.hpp"
#include "libhydro/waves/dispersion.hpp"
#include "libhydro/waves/sea.hpp"
#include "libstruct/model/assembler.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);
constexpr double kFoot = 0.3048;                 // m
constexpr double kPoundForce = 4.4482216152605;  // N

// A 40 ft tether in 60 ft of fresh water with a buoy on top, in US units, gravity not given.
const char* kUsOcean = R"(units: US
materials:
  rope: {type: linear_elastic, E: 1.0e7 psf}
sections:
  rope: {material: rope, area: 0.001 ft^2, density: 2 slug/ft^3,
         hydro: {diameter: 0.5 in, Cn: 1.2, Ct: 0.02, Ca: 1.0, CaAx: 0.1,
                 tangential_drag_area: diameter, per_length: unstretched}}
lines:
  - {name: tether, from: [0, 0, -60 ft], to: [0, 0, -20 ft], elements: 4, order: 2, section: rope}
supports:
  - {node: tether.start, fix: [x, y, z]}
water: {density: 1.94 slug/ft^3, depth: 60 ft}
waves:
  kinematics_above_mean: constant
  front: {start: -100 ft, speed: phase, ramp: 2}
  components:
    - {height: 3 ft, period: 6 s, heading: 30 deg, phase: 90 deg}
current: {profile: power_law, speed: 2 ft/s, heading: 0, exponent: 7}
seabed: {friction: 0.6}
bodies:
  - {node: tether.end, type: sphere, diameter: 2 ft, Cd: 0.5, weight: 10 lbf}
steps:
  - static: {name: s}
)";

TEST(CaseReaderOcean, ConvertsWaterWavesAndDefaultsIntoTheCaseUnits) {
  const Case c = readCase(test::writeCase("ocean-us.yaml", kUsOcean));
  ASSERT_NE(c.sea, nullptr);
  const hydro::Water& w = c.sea->water();
  // Standard gravity in ft/s^2 when the case gives none: 9.80665 / 0.3048 = 32.17404856.
  EXPECT_NEAR(w.gravity, 9.80665 / kFoot, 1e-12);
  EXPECT_DOUBLE_EQ(w.density, 1.94);
  EXPECT_DOUBLE_EQ(w.depth, 60.0);
  ASSERT_EQ(c.sea->components().size(), 1u);
  const hydro::WaveComponent& k = c.sea->components()[0];
  EXPECT_DOUBLE_EQ(k.amplitude, 1.5);
  EXPECT_NEAR(k.heading, kPi / 6.0, 1e-15);  // 30 deg
  EXPECT_NEAR(k.phase, kPi / 2.0, 1e-15);    // 90 deg
  EXPECT_NEAR(k.omega, 2.0 * kPi / 6.0, 1e-15);
  EXPECT_DOUBLE_EQ(k.k, hydro::waveNumber(k.omega, 60.0, w.gravity));

  // The body's weight in air over g is a point mass at the tether's end: 10 / 32.174 slug.
  const model::Model& m = *c.model;
  ASSERT_EQ(m.elementCount(), 5);
  EXPECT_EQ(m.element(4).typeName(), "point_mass");
  // The body's water load, and (the case has seabed:) its contact with the bed.
  ASSERT_EQ(m.nodeLoads().size(), 2u);
  EXPECT_NE(dynamic_cast<const hydro::SeabedNodeLoad*>(m.nodeLoads()[1].get()), nullptr);
  const auto* body = dynamic_cast<const hydro::BodyNodeLoad*>(m.nodeLoads()[0].get());
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(body->node(), 4);                                         // the last of 5 nodes
  EXPECT_NEAR(body->body().volume, kPi * 8.0 / 6.0, 1e-14);           // pi D^3 / 6, ft^3
  EXPECT_NEAR(body->body().drag_area, 0.5 * kPi * 4.0 / 4.0, 1e-14);  // Cd pi D^2 / 4, ft^2
  EXPECT_DOUBLE_EQ(body->body().added_mass, 0.5);                     // a sphere's default

  // Morison (one load: every hydro section is per unstretched length) and seabed contact.
  ASSERT_EQ(m.lineLoads().size(), 2u);
  EXPECT_EQ(m.lineLoads()[0]->measure(), model::LengthMeasure::Reference);
  const auto* bed = dynamic_cast<const hydro::SeabedLineLoad*>(m.lineLoads()[1].get());
  ASSERT_NE(bed, nullptr);
  // MoorDyn's kBot = 3e6 Pa/m in lbf/ft^3 (= 3e6 ft^3 / lbf in SI): the force per length of a
  // point 0.01 ft into the bed at rest is kBot delta d, d = 0.5 in. Relative 1e-12 (rounding).
  model::LoadPoint p;
  p.element = 0;
  p.position = {0.0, 0.0, -60.01};
  const double k_bot = 3.0e6 * kFoot * kFoot * kFoot / kPoundForce;
  const double expected = k_bot * 0.01 * (0.5 / 12.0);
  EXPECT_NEAR(bed->evaluate(p, false).force.z(), expected, 1e-12 * expected);
}

TEST(CaseReaderOcean, CurrentProfilesFollowTheirConstructors) {
  // Power law U_s ((z + h) / h)^(1/n) with a reference depth other than the water's, heading
  // 90 deg (+y); still water otherwise. Reference: the formula, to 1e-14 relative.
  const std::string base = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  wire: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3}
lines:
  - {name: cable, from: [0, 0, -20 m], to: [10 m, 0, -20 m], elements: 2, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z]}
  - {nodes: cable, fix: [y]}
water: {density: 1025 kg/m^3, depth: 30 m}
steps:
  - static: {name: s}
)";
  const Case power = readCase(test::writeCase(
      "power.yaml", base + "current: {profile: power_law, speed: 1.5 m/s, heading: 90 deg, "
                           "exponent: 5, reference_depth: 40 m}\n"));
  const Eigen::Vector3d v = power.sea->at({0.0, 0.0, -10.0}, 0.0).velocity;
  const double u = 1.5 * std::pow(30.0 / 40.0, 1.0 / 5.0);
  EXPECT_NEAR(v.y(), u, 1e-14 * u);
  EXPECT_NEAR(v.x(), 0.0, 1e-15);

  // A table in cm/s, interpolated linearly: halfway between (-20 m, 10 cm/s) and (0, 50 cm/s).
  const Case table = readCase(test::writeCase(
      "table.yaml",
      base + "current:\n  profile: table\n  table: [[-20 m, 10 cm/s], [0 m, 50 cm/s]]\n"));
  EXPECT_NEAR(table.sea->at({0.0, 0.0, -10.0}, 0.0).velocity.x(), 0.3, 1e-15);
}

// A sloped and a tabulated bed: a line's end node 1 m under the bed is refused with the bed's
// height there (by hand: the plane -30 + 0.5 x at x = 10 m is -25 m; the grid's bilinear height
// at (10 m, 5 m), halfway between rows z = -22 and z = -26 m at x = 10 m, is -24 m), and the
// same line 1 m above it reads. A 2 s wave stepped at 0.5 s is a warning (4 steps a period).
TEST(CaseReaderOcean, NodesBelowASlopedOrTabulatedBedAreRefused) {
  const auto with = [](const std::string& end_z, const std::string& seabed) {
    return R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  wire: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3}
lines:
  - {name: cable, from: [0, 5 m, -20 m], to: [10 m, 5 m, )" +
           end_z + R"(], elements: 2, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z]}
water: {density: 1025 kg/m^3, depth: 30 m}
)" + seabed +
           R"(
steps:
  - static: {name: s}
)";
  };
  const std::string plane = "seabed: {slope: [0.5, 0]}";
  const std::string grid =
      "seabed:\n  grid: {x0: 0, dx: 10 m, y0: 0, dy: 10 m, z: [[-30 m, -22 m], [-30 m, -26 m]]}";
  const std::string below_plane = test::writeCase("below-plane.yaml", with("-26 m", plane));
  EXPECT_TRUE(test::anyContains(test::problems(below_plane),
                                below_plane +
                                    ":7: node 3: below the seabed (got z = -26 m, expected z >= "
                                    "-25 m, the bed's height at x = 10 m, y = 5 m)"))
      << test::joined(test::problems(below_plane));
  EXPECT_TRUE(test::problems(test::writeCase("above-plane.yaml", with("-24 m", plane))).empty());
  const std::string below_grid = test::writeCase("below-grid.yaml", with("-25 m", grid));
  EXPECT_TRUE(test::anyContains(test::problems(below_grid), "expected z >= -24 m"))
      << test::joined(test::problems(below_grid));
  EXPECT_TRUE(test::problems(test::writeCase("above-grid.yaml", with("-23 m", grid))).empty());

  const std::string waves = with("-20 m", "waves: [{height: 0.1 m, period: 2 s}]");
  const Case c = readCase(test::writeCase(
      "wave-step.yaml", waves.substr(0, waves.find("steps:")) +
                            "steps:\n  - dynamic: {name: d, schedule: [{dt: 0.5 s, steps: 4}]}\n"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("dt = 0.5 s is 0.25 times the period 2 s of wave 1 (line 12)"),
            std::string::npos)
      << c.warnings[0];
}

// A vertical tether from the bed holding a submerged buoy, in still water: the anchor carries the
// net buoyancy, rho g (V + A_d L) - (m_b + rho_s A L) g, by hand:
//   rho g V    = 1025 * 9.81 * pi / 6         (sphere D = 1 m)
//   rho g A_d L = 1025 * 9.81 * pi 0.02^2 / 4 * 40   (per unstretched length)
//   weights    = (100 + 7850 * 1e-4 * 40) * 9.81
// Measured: 1.4e-12 relative (the static step's convergence); tolerance 1e-10.
TEST(CaseReaderOcean, TetheredBuoyLoadsItsAnchorWithTheNetBuoyancy) {
  const std::string text = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  tether: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3,
           hydro: {diameter: 0.02 m, Cn: 1.2, Ca: 1.0, per_length: unstretched}}
lines:
  - {name: tether, from: [0, 0, -50 m], to: [0, 0, -10 m], elements: 4, order: 2, section: tether}
supports:
  - {node: tether.start, fix: [x, y, z]}
  - {nodes: tether, fix: [x, y]}
loads:
  gravity: {g: 9.81 m/s^2}
water: {density: 1025 kg/m^3, depth: 50 m}
bodies:
  - {node: tether.end, type: sphere, diameter: 1 m, Cd: 0.5, mass: 100 kg}
steps:
  - static: {name: s}
summary:
  anchor_z: {quantity: reaction_z, node: tether.start}
)";
  const double g = 9.81, rho = 1025.0;
  const double up = rho * g * (kPi / 6.0 + kPi * 0.02 * 0.02 / 4.0 * 40.0);
  const double down = (100.0 + 7850.0 * 1e-4 * 40.0) * g;
  const double measured = test::summaryValue(test::runCaseText("tethered-buoy", text), "anchor_z");
  EXPECT_NEAR(measured, -(up - down), 1e-10 * (up - down));
}

// loads: wave_pressure: on a fixed 2 m x 0.5 m rectangle (a stay hanging from it, free along z) of Q8s 5 m down in still water (normal
// side1 x side2 = +z), water on its positive side: one surface load on its 4 membranes (not on the
// line's cable), and the external load at load factor 1 sums to -rho g d A e_z = -50259.08 N.
// Reference: rho g d A by hand; tolerance 1e-12 relative (Gauss integrates a constant exactly).
TEST(CaseReaderOcean, WavePressureOnASurfaceIsTheHydrostaticResultant) {
  const Case c = readCase(test::writeCase("wave-pressure.yaml", R"(units: SI
materials:
  rubber: {type: mooney_rivlin, C1: 1 MPa, C2: 0.1 MPa}
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  sheet: {material: rubber, thickness: 1 mm}
  wire: {material: steel, area: 1.0e-4 m^2}
surfaces:
  - {name: lid, shape: rectangle, corner: [0, 0, -5 m], side1: [2 m, 0, 0], side2: [0, 0.5 m, 0],
     element: Q8, divisions: [2, 2], section: sheet}
lines:
  - {name: stay, from: [0, 0, -5 m], to: [0, 0, -6 m], elements: 1, order: 2, section: wire}
supports:
  - {nodes: all, fix: [x, y]}
  - {nodes: lid, fix: [z]}
loads:
  wave_pressure:
    - {on: lid, water_side: positive}
water: {density: 1025 kg/m^3, depth: 30 m}
steps:
  - static: {}
)"));
  const model::Model& m = *c.model;
  ASSERT_EQ(m.surfaceLoads().size(), 1u);
  EXPECT_EQ(m.surfaceLoads()[0].elements.size(), 4u);
  const auto* wave =
      dynamic_cast<const hydro::IncidentPressureLoad*>(m.surfaceLoads()[0].load.get());
  ASSERT_NE(wave, nullptr);
  EXPECT_EQ(wave->side(), hydro::WaterSide::Positive);
  const model::Assembler assembler(m);
  model::State s = m.initialState();
  s.load_factor = 1.0;
  const Eigen::Vector3d total = test::totalExternalLoad(assembler, s);
  const double expected = -1025.0 * 9.80665 * 5.0 * 2.0 * 0.5;
  EXPECT_NEAR(total.z(), expected, 1e-12 * std::abs(expected));
  EXPECT_LT(total.head<2>().norm(), 1e-12 * std::abs(expected));
}

}  // namespace
}  // namespace flexmoor::app
