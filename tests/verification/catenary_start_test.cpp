// A line's `initial_shape: catenary` on a plain case (no scenario, no water, no seabed): a steel
// wire hanging between supports 80 m apart and 20 m up, 100 m unstretched (EA = 2e7 N, w =
// 7.70085 N/m, the catenary's law `strain: engineering`), its reference the straight unstretched
// line and its upper end moved into place by its support. Newton starts on the elastic catenary
// and stays there: the FE reactions match the product catenary (libhydro/mooring), H to 1.5e-6,
// V to 2e-7 and the lower support's V_A to 3e-7 (measured -9.2e-7, -8.6e-8 and 1.4e-7 on 20 L4
// elements) within 6 iterations (measured 4).
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "libhydro/mooring/catenary_line.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

const char* kHangingWire = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa, strain: engineering}
sections:
  wire: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3}
lines:
  - {name: cable, from: [0, 0, 0], to: [100 m, 0, 0], elements: 20, order: 4, section: wire,
     initial_shape: catenary}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [-20 m, 0, 20 m]}
loads:
  gravity: {g: 9.81}
steps:
  - static: {name: hang}
summary:
  H: {quantity: reaction_horizontal, node: cable.end}
  V: {quantity: reaction_z, node: cable.end}
  anchor_z: {quantity: reaction_z, node: cable.start}
)";

TEST(CatenaryStart, HangingWireStartsOnItsCatenaryAndStaysThere) {
  const auto dir = scratch("catenary-start");
  const CliRun r = runText(dir, "hanging-wire", kHangingWire);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(in 1 increments \((\d+) iterations)")))
      << r.output;
  EXPECT_LE(std::stoi(m[1]), 6);
  hydro::CatenaryLineInputs in;
  in.horizontal_span = 80.0;
  in.vertical_span = 20.0;
  in.unstretched_length = 100.0;
  in.weight = 7850.0 * 1.0e-4 * 9.81;
  in.axial_stiffness = 2.0e11 * 1.0e-4;
  in.seabed = false;
  const hydro::CatenaryLine line = hydro::solveCatenary(in);
  const std::string json = readSummary(dir);
  EXPECT_NEAR(summaryValue(json, "H") / line.horizontal, 1.0, 1.5e-6);
  EXPECT_NEAR(summaryValue(json, "V") / line.vertical, 1.0, 2e-7);
  // The lower support holds the line up: the force on it is V_A = V - w L < 0, downward.
  EXPECT_NEAR(summaryValue(json, "anchor_z") / -line.anchor_vertical, 1.0, 3e-7);
}

}  // namespace
}  // namespace flexmoor::test
