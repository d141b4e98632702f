// The platform's motion of scenario: spread_mooring given as a table of samples or a file of
// time series (apps/case/read/read_motion.hpp: the not-a-knot cubic spline through the samples)
// against the sine it was sampled from: one OC3-Hywind line (docs/theory.md#oc3-hywind) whose
// fairlead surges 2 sin(2 pi t / 10 s) m, a 20 s dynamic run. The sine's run is the reference; the table's
// differs by the spline's error alone (tests/unit/cubic_spline_function_test.cpp: at a spacing h
// = 0.25 s, 1.4e-5 m in position and 3.8e-4 m/s in velocity at most), and the file's (the same
// samples) is the table's, and so is that of a tab-separated file without a header whose times
// are 100 s later (MoorDyn's and OpenFAST's layout: columns by number, time_offset: -100 s).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);

const char* kCase = R"(
scenario: spread_mooring
units: SI
water: {density: 1025 kg/m^3, depth: 320 m}
gravity: 9.80665 m/s^2
seabed: {stiffness: 3.0e6 Pa/m, damping: 3.0e5 Pa*s/m}
line_types:
  chain: {diameter: 0.09 m, mass_per_length: 77.7066 kg/m, EA: 384.243e6 N, Cn: 1.6, Ct: 0.1,
          Ca: 1.0, CaAx: 0.0, per_length: unstretched, damping: {BA: 1.559e6 N*s}}
mooring_lines:
  - {anchor: [853.87, 0, -320 m], fairlead: [5.2, 0, -70 m], length: 902.2 m, type: chain,
     elements: 20, order: 3}
platform:
  surge: SURGE
  ramp: 0 s      # the sine from full speed, as its samples in the table and the file give it
dynamic: {name: surge, dt: 0.1 s, steps: 200, hht_alpha: -0.1, criterion: displacement,
          load_matrices: iteration}
summary:
  x_at_7_3: {quantity: position_x, node: line_1.end, at: 7.3 s}
  v_at_7_3: {quantity: velocity_x, node: line_1.end, at: 7.3 s}
  x_at_16: {quantity: position_x, node: line_1.end, at: 16 s}
  v_at_16: {quantity: velocity_x, node: line_1.end, at: 16 s}
  tension_max: {quantity: end_tension, element: 20, end: last, stat: max, window: {from: 5 s}}
  tension_min: {quantity: end_tension, element: 20, end: last, stat: min, window: {from: 5 s}}
)";

// Samples of the surge every 0.25 s over [0, 25] s.
std::vector<std::pair<double, double>> samples() {
  std::vector<std::pair<double, double>> s;
  for (int k = 0; k <= 100; ++k)
    s.emplace_back(0.25 * k, 2.0 * std::sin(2.0 * kPi * 0.25 * k / 10.0));
  return s;
}

std::string run(const std::string& name, const std::string& surge, const std::string& csv = "",
                const std::string& file_name = "motion.csv") {
  const auto dir = scratch(name);
  if (!csv.empty()) std::ofstream(dir / file_name) << csv;
  const CliRun r = runText(dir, name, std::regex_replace(kCase, std::regex("SURGE"), surge), " --no-figure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return readSummary(dir);
}

// The fairlead's position and velocity are the sine's to the spline's bound inside a table of
// spacing h = 0.25 s (h^4 w^4 A / 300 = 4.1e-6 m, h^3 w^4 A / 100 = 4.9e-5 m/s; measured 1.3e-6
// m and 3.9e-5 m/s at 7.3 s, 0 and 3.4e-6 m/s at 16 s, a sample), exactly x_F + 2 sin(2 pi t /
// 10 s) for the sine (1e-9 m); the tension extremes after 5 s within 2e-5 of the sine's
// (measured 2.9e-6); the file's run equals the table's (1e-12).
TEST(PlatformMotionTable, TableAndFileReproduceTheSine) {
  const std::string sine = run("surge-sine", "{amplitude: 2.0 m, period: 10 s}");
  std::ostringstream table, csv;
  csv << "# surge of the platform, m\ntime, heave, surge\n";
  table << "{table: [";
  for (const auto& [t, x] : samples()) {
    table << (t > 0.0 ? ", " : "") << "[" << t << " s, " << std::setprecision(17) << x << " m]";
    csv << std::setprecision(17) << t << ", 0, " << x << "\n";
  }
  table << "]}";
  const std::string tabled = run("surge-table", table.str());
  const std::string filed = run("surge-file", "{file: motion.csv, column: surge}", csv.str());
  for (const auto& [key, t] : {std::pair{"x_at_7_3", 7.3}, {"x_at_16", 16.0}}) {
    EXPECT_NEAR(summaryValue(sine, key), 5.2 + 2.0 * std::sin(2.0 * kPi * t / 10.0), 1e-9) << key;
    EXPECT_NEAR(summaryValue(tabled, key), summaryValue(sine, key), 4.1e-6) << key;
  }
  for (const char* key : {"v_at_7_3", "v_at_16"})
    EXPECT_NEAR(summaryValue(tabled, key), summaryValue(sine, key), 4.9e-5) << key;
  for (const char* key : {"tension_max", "tension_min"})
    EXPECT_NEAR(summaryValue(tabled, key) / summaryValue(sine, key), 1.0, 2e-5) << key;
  for (const char* key :
       {"x_at_7_3", "v_at_7_3", "x_at_16", "v_at_16", "tension_max", "tension_min"})
    EXPECT_NEAR(summaryValue(filed, key), summaryValue(tabled, key),
                1e-12 * std::abs(summaryValue(tabled, key)))
        << key;
}

// The samples of the table above in a tab-separated file without a header, time 100 s on in
// column 1, the surge in column 3, leading blanks and a '#' comment; `time_offset: -100 s` puts
// them at the table's times (exactly: multiples of 0.25 s plus 100), so the run is the table's.
TEST(PlatformMotionTable, TabSeparatedFileWithoutAHeaderIsTheTable) {
  std::ostringstream table, tabs;
  table << "{table: [";
  tabs << "# t (s)\theave (m)\tsurge (m), 100 s into a run\n";
  for (const auto& [t, x] : samples()) {
    table << (t > 0.0 ? ", " : "") << "[" << t << " s, " << std::setprecision(17) << x << " m]";
    tabs << "  " << std::setprecision(17) << t + 100.0 << "\t0.0\t" << x << "\n";
  }
  table << "]}";
  const std::string tabled = run("surge-table-2", table.str());
  const std::string filed = run("surge-tabs", "{file: motion.dat, column: 3, time_offset: -100 s}",
                                tabs.str(), "motion.dat");
  for (const char* key :
       {"x_at_7_3", "v_at_7_3", "x_at_16", "v_at_16", "tension_max", "tension_min"})
    EXPECT_NEAR(summaryValue(filed, key), summaryValue(tabled, key),
                1e-12 * std::abs(summaryValue(tabled, key)))
        << key;
  EXPECT_NEAR(summaryValue(filed, "x_at_7_3"), 5.2 + 2.0 * std::sin(2.0 * kPi * 0.73), 4.1e-6);
}

}  // namespace
}  // namespace flexmoor::test
