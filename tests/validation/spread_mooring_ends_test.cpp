// The default summary of scenario: spread_mooring at each end of a line, with the ends and signs
// the scenario states (apps/case/scenarios/spread_mooring.cpp, README): fairlead_horizontal_k and
// fairlead_vertical_k are the fairlead support's reaction on the line (the upward pull that holds
// it: V_F > 0), anchor_horizontal_k and anchor_vertical_k the line's pull on the anchor (upward
// +: an uplift), the tensions the end elements' forces at those ends. A taut wire, fully
// suspended (spans 300 m and 180 m, L = 349 m, 0.26% short of the chord; d 0.1 m, 50 kg/m,
// EA 1e9 N, 20 L4), whose anchor is lifted: in still water against the test-side elastic
// catenary (tests/support/mooring_catenary), and in a 2 m/s current along the line, whose drag
// makes the two ends' horizontal forces differ, against each end's own force balance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/cli_run.hpp"
#include "tests/support/mooring_catenary.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);

// The wire with a dynamic step of 10 steps of 0.1 s at rest (nothing moves it), and `extra`.
std::string tautWire(const std::string& extra) {
  return R"(scenario: spread_mooring
title: a taut wire lifting its anchor
units: SI
water: {density: 1025 kg/m^3, depth: 200 m}
gravity: 9.80665 m/s^2
line_types:
  wire: {diameter: 0.1 m, mass_per_length: 50 kg/m, EA: 1.0e9 N, Cn: 1.2, Ct: 0.02, Ca: 1.0,
         CaAx: 0.0, per_length: unstretched}
mooring_lines:
  - {anchor: [300 m, 0, -200 m], fairlead: [0, 0, -20 m], length: 349 m, type: wire,
     elements: 20, order: 4}
dynamic: {name: rest, dt: 0.1 s, steps: 10}
)" + extra;
}

struct Ends {
  double fairlead_tension, fairlead_horizontal, fairlead_vertical;
  double anchor_tension, anchor_horizontal, anchor_vertical;
};

Ends ends(const std::string& json) {
  return {summaryValue(json, "fairlead_tension_static_1"),
          summaryValue(json, "fairlead_horizontal_static_1"),
          summaryValue(json, "fairlead_vertical_static_1"),
          summaryValue(json, "anchor_tension_static_1"),
          summaryValue(json, "anchor_horizontal_static_1"),
          summaryValue(json, "anchor_vertical_static_1")};
}

// Still water: H at both ends, V_F at the fairlead, the anchor lifted by V_A = V_F - w L, the end
// tensions hypot(H, V_F) and hypot(H, V_A), w = (50 - 1025 pi 0.1^2 / 4) 9.80665 N/m: relative
// 2e-11 (measured 1.0e-11 at most: H 2,188,866 N, V_F 1,385,452 N, V_A 1,241,878 N). The dynamic
// step at rest keeps them: its extremes anchor_vertical_max_1 and fairlead_tension_max_1 / _min_1
// equal the static values to 1e-11 (measured 4.8e-12). A sign flipped (anchor_vertical as the
// anchor support's reaction on the line, -V_A) fails by 2.
TEST(SpreadMooringEnds, TautLineMatchesTheCatenaryWithTheStatedSigns) {
  const std::string json = runCaseText("taut-wire-ends", tautWire(""));
  const Ends f = ends(json);
  const double w = (50.0 - 1025.0 * kPi * 0.1 * 0.1 / 4.0) * 9.80665, length = 349.0;
  const MooringLineSolution ref = solveMooringLine({300.0, 180.0, length, w, 1.0e9});
  ASSERT_EQ(ref.seabed_length, 0.0);
  const double h = ref.horizontal_force, vf = ref.fairlead_vertical, va = vf - w * length;
  ASSERT_GT(va, 0.0);
  const double tol = 2e-11;
  EXPECT_NEAR(f.fairlead_horizontal / h, 1.0, tol);
  EXPECT_NEAR(f.anchor_horizontal / h, 1.0, tol);
  EXPECT_NEAR(f.fairlead_vertical / vf, 1.0, tol);
  EXPECT_NEAR(f.anchor_vertical / va, 1.0, tol);
  EXPECT_NEAR(f.fairlead_tension / std::hypot(h, vf), 1.0, tol);
  EXPECT_NEAR(f.anchor_tension / std::hypot(h, va), 1.0, tol);
  EXPECT_NEAR(summaryValue(json, "anchor_vertical_max_1") / f.anchor_vertical, 1.0, 1e-11);
  EXPECT_NEAR(summaryValue(json, "fairlead_tension_max_1") / f.fairlead_tension, 1.0, 1e-11);
  EXPECT_NEAR(summaryValue(json, "fairlead_tension_min_1") / f.fairlead_tension, 1.0, 1e-11);
}

// A 2 m/s current along +x (from the fairlead's side towards the anchor) drags the wire: the
// fairlead holds more than the anchor (H_F - H_A > 0.5% of H_F; measured 0.67%). Each end's
// horizontal and vertical forces make that end's tension: hypot(H_F, V_F) = T_F and
// hypot(H_A, V_A) = T_A, 1e-15 relative (measured 0: one force); the fairlead's horizontal force
// taken at the anchor, hypot(H_A, V_F), misses the drag and fails by -4.8e-3. The anchor is still
// lifted (V_A > 0).
TEST(SpreadMooringEnds, InACurrentEachEndKeepsItsOwnForces) {
  const Ends f =
      ends(runCaseText("taut-wire-current",
                       tautWire("current: {profile: uniform, speed: 2 m/s, heading: 0 deg}\n")));
  EXPECT_GT((f.fairlead_horizontal - f.anchor_horizontal) / f.fairlead_horizontal, 0.005);
  EXPECT_NEAR(std::hypot(f.fairlead_horizontal, f.fairlead_vertical) / f.fairlead_tension, 1.0,
              1e-15);
  EXPECT_NEAR(std::hypot(f.anchor_horizontal, f.anchor_vertical) / f.anchor_tension, 1.0, 1e-15);
  EXPECT_GT(f.anchor_vertical, 0.0);
}

}  // namespace
}  // namespace flexmoor::test
