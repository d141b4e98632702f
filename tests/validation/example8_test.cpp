// Example 8, the relaxation test (cases/seed/ex8-relaxation-test.yaml): a buoy held displaced on
// a light rope under water is released and rises for 3 s. The experiment's series were not
// recovered (docs/theory.md#example-8), so the checks are the required ones and physics:
//  - convergence: halving dt and doubling the elements each move the buoy's position at 1 s and
//    3 s by under 1% (required); held to 3e-5 (dt; measured 1.7e-5, z at 3 s) and 2e-3 (mesh;
//    measured 1.1e-3, x at 1 s);
//  - the buoy rises and swings towards the vertical above the anchor, never further from the
//    anchor than the rope stretched by the largest anchor tension allows;
//  - its speed stays below the terminal rise speed of the free buoy, sqrt(2 B_net / (rho CdA)) =
//    40.54 in/s (net buoyancy 0.121 lbf, water 1.94364 slug/ft^3, CdA 0.0109083 ft^2): the rope's
//    tension and drag only slow it;
//  - the anchor tension while held is the rope's submerged weight's share and far below the
//    released peak, which the buoy's net buoyancy 0.121 lbf plus its deceleration bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

std::string caseText(const std::string& name) {
  std::string text =
      readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/seed/ex8-relaxation-test.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  replace("name: ex8-relaxation-test", "name: " + name);
  if (name.find("dt") != std::string::npos) {
    replace("dt: 0.005 s", "dt: 0.0025 s");
    replace("steps: 600", "steps: 1200");
  }
  if (name.find("mesh") != std::string::npos)
    replace("elements: 4, order: 3", "elements: 8, order: 3");
  return text;
}

struct Buoy {
  double x1, z1, x3, z3, speed_max, tension_max, held_tension;
};

// The summary is in the case's units (ft, ft/s, lbf); the checks below in inches, 12 to the foot.
Buoy run(const std::string& name) {
  const std::string json = runCaseText(name, caseText(name));
  EXPECT_NE(json.find("\"buoy_x_t1\": \"ft\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"buoy_speed_max\": \"ft/s\""), std::string::npos) << json;
  const double in = 12.0;
  return {in * summaryValue(json, "buoy_x_t1"),      in * summaryValue(json, "buoy_z_t1"),
          in * summaryValue(json, "buoy_x_t3"),      in * summaryValue(json, "buoy_z_t3"),
          in * summaryValue(json, "buoy_speed_max"), summaryValue(json, "anchor_tension_max"),
          summaryValue(json, "held_anchor_tension")};
}

void expectClose(const Buoy& a, const Buoy& b, double tolerance, const char* what) {
  for (const auto& [p, q] : {std::pair{a.x1, b.x1}, {a.z1, b.z1}, {a.x3, b.x3}, {a.z3, b.z3}})
    EXPECT_NEAR(p / q, 1.0, tolerance) << what;
}

TEST(Example8, ConvergesInTimeStepAndMesh) {
  const Buoy base = run("ex8-base"), half_dt = run("ex8-dt"), fine = run("ex8-mesh");
  expectClose(half_dt, base, 3e-5, "dt halved");
  expectClose(fine, base, 2e-3, "elements doubled");
}

TEST(Example8, TheBuoyRisesOnItsRopeBelowItsTerminalSpeed) {
  const Buoy b = run("ex8-physics");
  // Held at (50, 50) in: at 1 s it has risen and swung in, more so at 3 s.
  EXPECT_LT(b.x1, 50.0);
  EXPECT_GT(b.z1, 50.0);
  EXPECT_LT(b.x3, b.x1);
  EXPECT_GT(b.z3, b.z1);
  const double rope = 71.56, ea = 4.8;
  for (const auto& [x, z] : {std::pair{b.x1, b.z1}, {b.x3, b.z3}})
    EXPECT_LE(std::hypot(x, z), rope * (1.0 + b.tension_max / ea));
  // At 3 s the rope is nearly taut: within 3% of its stretched length from the anchor.
  EXPECT_GT(std::hypot(b.x3, b.z3), 0.97 * rope);
  const double terminal = 12.0 * std::sqrt(2.0 * 0.121 / (1.94364 * 0.0109083));  // in/s
  EXPECT_NEAR(terminal, 40.54, 0.01);
  EXPECT_GT(b.speed_max, 0.2 * terminal);
  EXPECT_LT(b.speed_max, terminal);
  // Held: the rope (submerged weight 2.381e-3 lbf/ft x 5.96 ft = 0.0142 lbf) hangs between two
  // supports, each carrying part of it. Released: the anchor takes the buoy's pull.
  EXPECT_GT(b.held_tension, 0.0);
  EXPECT_LT(b.held_tension, 2.381e-3 * 71.56 / 12.0);
  EXPECT_GT(b.tension_max, 0.121 * 0.8);
  EXPECT_LT(b.tension_max, 2.0 * 0.121);
}

}  // namespace
}  // namespace flexmoor::test
