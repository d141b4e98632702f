// Lines whose ends are both in the water (scenario: spread_mooring, run in process): an anchor
// 10 m above a 100 m deep bed whose chain dips onto the bed between anchor and fairlead, against
// the test-side elastic catenary laid between its two hanging parts (the same H in both;
// tests/support/laid_between_hanging_parts), and mid-water lines that hang clear of the bed,
// taut and slack, against the product's suspended catenary. Each starts on its catenary, never
// below the bed, and static Newton reaches the equilibrium from there.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>

#include "apps/case/case_reader.hpp"
#include "libhydro/mooring/catenary_line.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/in_process_run.hpp"
#include "tests/support/laid_between_hanging_parts.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);
// OC3-Hywind's chain in 1025 kg/m^3 water at g = 9.80665 m/s^2 (docs/theory.md#oc3-hywind).
const double kWeight = (77.7066 - 1025.0 * kPi * 0.09 * 0.09 / 4.0) * 9.80665;
const double kEA = 384.243e6;

// One line of that chain from `anchor` to `fairlead` (x and z, m) in 100 m of water.
std::string chainCase(double anchor_x, double anchor_z, double fairlead_z, double length) {
  return R"(scenario: spread_mooring
units: SI
water: {density: 1025 kg/m^3, depth: 100 m}
gravity: 9.80665 m/s^2
seabed: {stiffness: 3.0e6 Pa/m, damping: 3.0e5 Pa*s/m}
line_types:
  chain: {diameter: 0.09 m, mass_per_length: 77.7066 kg/m, EA: 384.243e6 N, Cn: 1.6, Ca: 1.0,
          per_length: unstretched}
mooring_lines:
  - {anchor: [)" +
         std::to_string(anchor_x) + ", 0, " + std::to_string(anchor_z) + " m], fairlead: [0, 0, " +
         std::to_string(fairlead_z) + " m], length: " + std::to_string(length) + R"( m, type: chain,
     elements: 20, order: 4}
)";
}

// The static step's Newton iterations from the start and its closing |R| / S (the log's).
struct NewtonRecord {
  int iterations = -1;
  double residual = NAN;
};

NewtonRecord newtonRecord(const std::string& log) {
  NewtonRecord r;
  std::smatch m;
  if (std::regex_search(log, m,
                        std::regex(R"(iterations (\d+)  max\|du\|/L \S+  \|R\|/S (\S+))"))) {
    r.iterations = std::stoi(m[1]);
    r.residual = std::stod(m[2]);
  }
  return r;
}

// No node of the line starts below the bed (z = -100 m; 1e-9 m).
void expectStartAboveTheBed(const std::string& name, const std::string& text) {
  const auto dir = scratch(name);
  const std::string file = (dir / (name + ".yaml")).string();
  { std::ofstream(file) << text; }
  const app::Case c = app::readCase(file);
  const model::State start = c.model->startState();
  const model::NodalField& X = c.model->reference();
  for (int n = 0; n < c.model->nodeCount(); ++n)
    EXPECT_GE(X(2, n) + start.displacement(2, n), -100.0 - 1e-9) << "node " << n + 1;
}

// The raised anchor: 500 m from the fairlead (z = -10 m), 10 m above the bed, 520 m of chain:
// 89 m hang from the anchor down to the bed, 150 m lie on it, 281 m hang from the fairlead
// (H = 273 kN). Newton from the start, no relaxation, in at most 8 iterations (measured 6) to
// |R| / S below 1e-8 (measured 6.5e-9). Against the catenary laid between its parts: the fairlead
// tension, its H and the anchor's tension within 2e-4 (measured 1.1e-4, 1.4e-4 and 1.7e-4 on 20
// L4 elements) and the laid length within 0.15 m (measured 0.09 m: the bed's force over w, the
// penalty bed's touchdowns spread over an element).
TEST(RaisedAnchorMooring, LaidBetweenHangingPartsMatchesItsCatenary) {
  const std::string text = chainCase(500.0, -90.0, -10.0, 520.0);
  expectStartAboveTheBed("raised-anchor", text);
  const InProcessRun run = runCaseInProcess("raised-anchor", text);
  ASSERT_EQ(run.exit_code, app::kSuccess) << run.log;
  EXPECT_EQ(run.log.find("relaxing"), std::string::npos) << run.log;
  const NewtonRecord newton = newtonRecord(run.log);
  EXPECT_GE(newton.iterations, 1) << run.log;
  EXPECT_LE(newton.iterations, 8) << run.log;
  EXPECT_LT(newton.residual, 1e-8) << run.log;
  LaidBetweenInputs in;
  in.horizontal_span = 500.0;
  in.anchor_height = 10.0;
  in.fairlead_height = 90.0;
  in.unstretched_length = 520.0;
  in.submerged_weight = kWeight;
  in.axial_stiffness = kEA;
  const LaidBetweenSolution ref = solveLaidBetween(in);
  EXPECT_NEAR(run.value("fairlead_tension_static_1") / ref.fairleadTension(), 1.0, 2e-4);
  EXPECT_NEAR(run.value("fairlead_horizontal_static_1") / ref.horizontal_force, 1.0, 2e-4);
  EXPECT_NEAR(run.value("anchor_tension_static_1") / ref.anchorTension(), 1.0, 2e-4);
  EXPECT_NEAR(run.value("length_on_seabed_static_1"), ref.laid_length, 0.15);
}

// Mid-water: anchor 50 m above the bed, fairlead 90 m above it and 100 m away, a taut 110 m and
// a slack 140 m line (its anchor pulled down by 33 kN: it dips from the anchor), both clear of
// the bed. Newton from the start in at most 6 iterations (measured 2 and 4) to |R| / S below
// 1e-8, the fairlead tension within 5e-7 of the product's suspended catenary (measured 1.2e-8
// and 4.0e-7 on 20 L4 elements).
TEST(RaisedAnchorMooring, MidWaterLinesHangClearOfTheBed) {
  for (const double length : {110.0, 140.0}) {
    const std::string text = chainCase(100.0, -50.0, -10.0, length);
    expectStartAboveTheBed("mid-water", text);
    const InProcessRun run = runCaseInProcess("mid-water", text);
    ASSERT_EQ(run.exit_code, app::kSuccess) << run.log;
    EXPECT_EQ(run.log.find("relaxing"), std::string::npos) << run.log;
    const NewtonRecord newton = newtonRecord(run.log);
    EXPECT_LE(newton.iterations, 6) << run.log;
    EXPECT_LT(newton.residual, 1e-8) << run.log;
    hydro::CatenaryLineInputs in;
    in.horizontal_span = 100.0;
    in.vertical_span = 40.0;
    in.unstretched_length = length;
    in.weight = kWeight;
    in.axial_stiffness = kEA;
    in.seabed = false;
    const hydro::CatenaryLine line = hydro::solveCatenary(in);
    EXPECT_NEAR(run.value("fairlead_tension_static_1") / line.fairleadTension(), 1.0, 5e-7)
        << length;
    EXPECT_EQ(run.value("length_on_seabed_static_1"), 0.0) << length;
  }
}

}  // namespace
}  // namespace flexmoor::test
