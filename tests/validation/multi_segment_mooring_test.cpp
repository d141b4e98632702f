// Multi-segment spread-mooring lines (scenario: spread_mooring with segments: and attachments:):
// the named case cases/ocean/chain-wire-chain-statics.yaml against the line's own
// multi-segment elastic catenary (checked against the integrated catenary equations in
// tests/hydro/multi_segment_catenary_test.cpp), its start on that catenary, the weight balance of
// length_on_seabed across segments of different weights, and two lines that must be the same: a
// one-type line split into segments, and a line with an attachment of zero net force; and
// cases/ocean/chain-wire-chain-motion.yaml, the lines carried by a platform moved by a file.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "apps/case/case_reader.hpp"
#include "libhydro/mooring/catenary_line.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0), kG = 9.80665, kRho = 1025.0;

double submerged(double mass_per_length, double diameter) {
  return (mass_per_length - kRho * kPi * diameter * diameter / 4.0) * kG;
}

// The named case's line (see its header): spans 655 m and 185 m; chain 300 m, wire 300 m, chain
// 100 m; a clump of 4000 kg and 0.5 m^3 at the first connection.
hydro::CatenaryLineInputs chainWireChain() {
  hydro::CatenaryLineInputs in;
  in.horizontal_span = 655.0;
  in.vertical_span = 185.0;
  const double chain = submerged(77.7066, 0.09), wire = submerged(30.0, 0.076);
  in.segments = {{300.0, chain, 384.243e6}, {300.0, wire, 5.5e8}, {100.0, chain, 384.243e6}};
  in.connection_forces = {(kRho * 0.5 - 4000.0) * kG, 0.0};
  return in;
}

// The FE equilibrium (12 + 6 + 3 L4 elements, penalty bed) against the catenary (rigid bed):
// fairlead tension, H, V and the anchor's force within 2e-4 (measured -1.3e-4 at most, on H; 40 + 24 + 12
// L4 elements give +1.8e-5: the mesh, not the start), the laid length within 0.1 m (measured
// +0.026 m), in at most 8 Newton iterations from the start (measured 5); every line alike.
TEST(MultiSegmentMooring, ChainWireChainMatchesItsCatenary) {
  const auto dir = scratch("chain-wire-chain");
  const CliRun r = flexmoor("run chain-wire-chain-statics -o " + dir.string() + " --no-figure");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(in 1 increments \((\d+) iterations)")))
      << r.output;
  EXPECT_LE(std::stoi(m[1]), 8);
  const std::string json = readSummary(dir);
  const hydro::CatenaryLine ref = hydro::solveCatenary(chainWireChain());
  ASSERT_GT(ref.laid_length, 0.0);
  ASSERT_LT(ref.laid_length, 300.0);  // the clump hangs: what the case is for
  for (int k = 1; k <= 3; ++k) {
    const std::string n = std::to_string(k);
    EXPECT_NEAR(summaryValue(json, "fairlead_tension_static_" + n) / ref.fairleadTension(), 1.0,
                2e-4);
    EXPECT_NEAR(summaryValue(json, "fairlead_horizontal_static_" + n) / ref.horizontal, 1.0, 2e-4);
    EXPECT_NEAR(summaryValue(json, "fairlead_vertical_static_" + n) / ref.vertical, 1.0, 2e-4);
    EXPECT_NEAR(summaryValue(json, "anchor_horizontal_static_" + n) / ref.anchor_horizontal, 1.0,
                2e-4);
    EXPECT_NEAR(summaryValue(json, "length_on_seabed_static_" + n), ref.laid_length, 0.1);
  }
}

// length_on_seabed over segments of different weights: in statics under weight, buoyancy and the
// bed alone, the bed carries what the fairlead does not, W - V_F with W the line's whole net
// weight (its segments' w_i L_i less the clump's net force); laid in the bottom chain, that is
// (W - V_F) / w_chain (1e-6 m; measured below 1e-7 m).
TEST(MultiSegmentMooring, LengthOnSeabedIsTheWeightTheFairleadDoesNotCarry) {
  const std::string json = runNamedCase("chain-wire-chain-statics");
  const hydro::CatenaryLineInputs in = chainWireChain();
  double weight = -in.connection_forces[0];
  for (const auto& s : in.segments) weight += s.weight * s.length;
  for (int k = 1; k <= 3; ++k) {
    const std::string n = std::to_string(k);
    const double expected =
        (weight - summaryValue(json, "fairlead_vertical_static_" + n)) / in.segments[0].weight;
    EXPECT_NEAR(summaryValue(json, "length_on_seabed_static_" + n), expected, 1e-6) << "line " << k;
  }
}

// The start: line_1 (its three segments' nodes, anchor to fairlead) on the catenary at each
// node's reference arc length (1e-9 m: the same profile evaluated again), the shared connection
// nodes once.
TEST(MultiSegmentMooring, LinesStartOnTheirCatenary) {
  const app::Case c = app::readCase(std::string(FLEXMOOR_SOURCE_DIR) +
                                    "/cases/ocean/chain-wire-chain-statics.yaml");
  const model::State start = c.model->startState();
  const hydro::CatenaryLine ref = hydro::solveCatenary(chainWireChain());
  const std::vector<int>& nodes = c.lines.at("line_1");
  ASSERT_EQ(nodes.size(), 12u * 3 + 6 * 3 + 3 * 3 + 1);
  const model::NodalField& X = c.model->reference();
  const Eigen::Vector3d anchor = X.col(nodes.front());
  EXPECT_NEAR((X.col(nodes.back()) - anchor).norm(), 700.0, 1e-9);
  for (const int n : nodes) {
    const hydro::CatenaryPoint p = ref.at((X.col(n) - anchor).norm());
    const Eigen::Vector3d y = X.col(n) + start.displacement.col(n);
    EXPECT_NEAR(y.x(), anchor.x() - p.x, 1e-9) << "node " << n;  // line 1 runs towards -x
    EXPECT_NEAR(y.y(), 0.0, 1e-9) << "node " << n;
    EXPECT_NEAR(y.z(), anchor.z() + p.z, 1e-9) << "node " << n;
  }
}

// One OC3 line (docs/theory.md#oc3-hywind) given three ways: one type, 20 L4 elements; two segments of the
// same chain, 10 + 10 L4 (the same nodes); and those two with a body of zero net force at the
// connection (1 m^3 and 1025 kg: buoyancy equal to weight). The three equilibria agree to 1e-8
// (Newton's tolerance; measured 5e-12 at most).
const char* kOc3Line = R"(
scenario: spread_mooring
units: SI
water: {density: 1025 kg/m^3, depth: 320 m}
gravity: 9.80665 m/s^2
seabed: {stiffness: 3.0e6 Pa/m, damping: 3.0e5 Pa*s/m}
line_types:
  chain: {diameter: 0.09 m, mass_per_length: 77.7066 kg/m, EA: 384.243e6 N, Cn: 1.6, Ct: 0.1,
          Ca: 1.0}
mooring_lines:
  - {anchor: [853.87, 0, -320 m], fairlead: [5.2, 0, -70 m], LINE}
)";

std::string oc3With(const std::string& line) {
  return std::regex_replace(kOc3Line, std::regex("LINE"), line);
}

TEST(MultiSegmentMooring, SplitLineAndZeroNetBodyChangeNothing) {
  const std::string whole =
      runCaseText("oc3-whole", oc3With("length: 902.2 m, type: chain, elements: 20, order: 4"));
  const std::string segments =
      "segments: [{type: chain, length: 451.1 m, elements: 10, order: 4}, "
      "{type: chain, length: 451.1 m, elements: 10, order: 4}]";
  const std::string split = runCaseText("oc3-split", oc3With(segments));
  const std::string body = runCaseText(
      "oc3-body", oc3With(segments + ", attachments: [{at: 1, mass: 1025 kg, volume: 1 m^3}]"));
  for (const char* key :
       {"fairlead_tension_static_1", "fairlead_horizontal_static_1", "fairlead_vertical_static_1",
        "anchor_tension_static_1", "length_on_seabed_static_1"}) {
    const double ref = summaryValue(whole, key);
    EXPECT_NEAR(summaryValue(split, key) / ref, 1.0, 1e-8) << key;
    EXPECT_NEAR(summaryValue(body, key) / ref, 1.0, 1e-8) << key;
  }
}

// cases/ocean/chain-wire-chain-motion.yaml: the platform's surge, heave and pitch from a CSV file
// sampled every h = 0.5 s from 2 sin(2 pi t / 10 s) m, 0.5 sin(2 pi t / 14 s + 0.4) m and 1.5
// sin(2 pi t / 25 s) degrees. Line 1's fairlead (rest (40, 0, -15) m, the reference at the
// origin) at 12.3 s is where that motion puts it, translation + Ry(pitch) arm, to the spline's
// bound inside a table (cubic_spline_function.hpp; h^4 w^4 A / 300 summed over surge and heave:
// 7e-5 m; measured 4.7e-5 m in x, 1.4e-6 m in z), its velocity surge' + pitch' (-40 sin - 15 cos)
// to h^3 w^4 A / 100 (4.2e-4 m/s; measured 1.6e-4 m/s). Lines 2 and 3 mirror each other across y
// = 0 under surge, heave and pitch: equal extremes (1e-9 relative; measured equal), and every
// line's tension range over t >= 10 s holds its statics tension (345,874 N, SG7).
TEST(MultiSegmentMooring, MotionFromAFileMovesTheFairleads) {
  const std::string json = runNamedCase("chain-wire-chain-motion");
  const double t = 12.3, w = 2.0 * kPi;
  const double surge = 2.0 * std::sin(w * t / 10.0),
               surge_rate = 2.0 * w / 10.0 * std::cos(w * t / 10.0);
  const double heave = 0.5 * std::sin(w * t / 14.0 + 0.4);
  const double pitch = 1.5 * kPi / 180.0 * std::sin(w * t / 25.0);
  const double pitch_rate = 1.5 * kPi / 180.0 * w / 25.0 * std::cos(w * t / 25.0);
  const double c = std::cos(pitch), s = std::sin(pitch);
  EXPECT_NEAR(summaryValue(json, "fairlead_x_1"), surge + 40.0 * c - 15.0 * s, 7e-5);
  EXPECT_NEAR(summaryValue(json, "fairlead_z_1"), heave - 40.0 * s - 15.0 * c, 7e-5);
  EXPECT_NEAR(summaryValue(json, "fairlead_vx_1"), surge_rate + pitch_rate * (-40.0 * s - 15.0 * c),
              4.2e-4);
  for (const char* stat : {"tension_min_", "tension_max_"})
    EXPECT_NEAR(
        summaryValue(json, std::string(stat) + "3") / summaryValue(json, std::string(stat) + "2"),
        1.0, 1e-9);
  for (int k = 1; k <= 3; ++k) {
    EXPECT_LT(summaryValue(json, "tension_min_" + std::to_string(k)), 345874.0) << "line " << k;
    EXPECT_GT(summaryValue(json, "tension_max_" + std::to_string(k)), 345874.0) << "line " << k;
  }
}

}  // namespace
}  // namespace flexmoor::test
