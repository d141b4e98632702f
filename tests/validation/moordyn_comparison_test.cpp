// flexmoor against MoorDyn-C v2.7.1 (commit 319ff99771cffb835fea4423306a0849692afd53) on
// identical inputs: MoorDyn's figures are data/reference/moordyn-*.csv, whose headers give the
// input files (written from flexmoor's cases by scripts/moordyn/write_input.py and
// write_ex8_input.py), the drivers (scripts/moordyn/surge_driver.c, release_driver.c), the
// resolutions and the commands; each test compares with the row MoorDyn converged at (`use`
// reference), each tolerance just above the difference measured (docs/validation.md, MoorDyn-C).
//  - OC4 and OC3 surge (the named cases, 600 s of 2 sin(2 pi t / 10 s) m at the fairleads, the
//    surge ramped in over its period in both codes): the fairlead tension extremes over t >= 100 s.
//    What differs besides the inputs: flexmoor's 12 L3 elements a line (their error against its
//    80 L3 run is 0.28% at most on OC4, 0.12% on OC3; the 80 L3 runs are within 0.02% of MoorDyn),
//    consistent mass and HHT-alpha against MoorDyn's lumped masses and RK2, and the seabed's
//    damping, which flexmoor brings in over the first 10% of the diameter and MoorDyn at once.
//  - Example 8 (the buoy released on its rope): the buoy's position at 1 s and 3 s, its largest
//    speed and the largest anchor force. The named case keeps the dissertation's conventions
//    (Morison loads and buoyancy per deformed length, Green's strain); MoorDyn's are per
//    unstretched length on the engineering strain, which the explicit model takes here to
//    compare like with like.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

// The row of data/reference/FILE whose `use` column is "reference", by column name.
std::map<std::string, double> moordynReference(const std::string& file) {
  std::ifstream in(std::string(FLEXMOOR_DATA_DIR) + "/reference/" + file);
  EXPECT_TRUE(in) << file;
  std::vector<std::string> header;
  std::map<std::string, double> row;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) fields.push_back(field);
    if (header.empty()) {
      header = fields;
      continue;
    }
    if (fields.size() != header.size() || fields.back() != "reference") continue;
    for (size_t i = 0; i + 1 < fields.size(); ++i) row[header[i]] = std::stod(fields[i]);
  }
  EXPECT_FALSE(row.empty()) << file << ": no reference row";
  return row;
}

// Runs a named case or a case file without VTK files or figures; its summary.json's text.
std::string runWithoutFigures(const std::string& case_or_file) {
  const std::string stem = std::filesystem::path(case_or_file).stem().string();
  const std::filesystem::path dir = scratch(stem + "-moordyn-" + std::to_string(getpid()));
  const CliRun r =
      flexmoor("run " + case_or_file + " -o " + dir.string() + " --no-vtk --no-figure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return readSummary(dir);
}

// The named surge case's fairlead tension extremes against MoorDyn's, line by line.
void expectSurgeMatchesMoorDyn(const std::string& case_name, const std::string& reference,
                               double tolerance) {
  const std::map<std::string, double> md = moordynReference(reference);
  const std::string json = runWithoutFigures(case_name);
  double worst = 0.0;
  for (int k = 1; k <= 3; ++k)
    for (const char* stat : {"min", "max"}) {
      const std::string n = std::to_string(k);
      const double ours = summaryValue(json, std::string("tension_") + stat + "_" + n);
      const double theirs = md.at(std::string("end_") + stat + "_" + n);
      EXPECT_NEAR(ours / theirs, 1.0, tolerance) << case_name << " line " << k << " " << stat;
      worst = std::max(worst, std::abs(ours / theirs - 1.0));
    }
  std::cout << "[ MoorDyn ] " << case_name << ": worst relative difference " << worst << "\n";
}

TEST(MoorDynComparison, Oc4SurgeFairleadTensionExtremes) {
  expectSurgeMatchesMoorDyn("oc4-semi-surge", "moordyn-oc4-surge.csv", 3e-3);
}

TEST(MoorDynComparison, Oc3SurgeFairleadTensionExtremes) {
  expectSurgeMatchesMoorDyn("oc3-hywind-surge", "moordyn-oc3-surge.csv", 1.5e-3);
}

struct Buoy {
  double x1, z1, x3, z3, speed_max, anchor_max;  // SI: m, m/s, N
};

Buoy buoyFromSummary(const std::string& json) {
  const double ft = 0.3048, lbf = 4.4482216152605;
  return {
      ft * summaryValue(json, "buoy_x_t1"),      ft * summaryValue(json, "buoy_z_t1"),
      ft * summaryValue(json, "buoy_x_t3"),      ft * summaryValue(json, "buoy_z_t3"),
      ft * summaryValue(json, "buoy_speed_max"), lbf * summaryValue(json, "anchor_tension_max")};
}

// Relative differences against MoorDyn's reference row, in the order of Buoy's fields.
std::vector<double> differences(const Buoy& b) {
  const std::map<std::string, double> md = moordynReference("moordyn-ex8.csv");
  return {b.x1 / md.at("x_t1_m") - 1.0,
          b.z1 / md.at("z_t1_m") - 1.0,
          b.x3 / md.at("x_t3_m") - 1.0,
          b.z3 / md.at("z_t3_m") - 1.0,
          b.speed_max / md.at("speed_max_m_s") - 1.0,
          b.anchor_max / md.at("anchor_force_max_N") - 1.0};
}

const char* const kBuoyFields[] = {"x at 1 s", "z at 1 s",  "x at 3 s",
                                   "z at 3 s", "max speed", "max anchor force"};

// The explicit model of Example 8 with MoorDyn's conventions (loads per unstretched length,
// engineering strain) and refined (32 L3, dt 0.00125 s): the same buoy path.
TEST(MoorDynComparison, Example8WithMoorDynsConventionsFollowsItsPath) {
  std::string text = readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/tests/cases/ex8-explicit.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("psf}", "psf, strain: engineering}");
  replace("per_length: deformed", "per_length: unstretched");
  replace("elements: 4, order: 3", "elements: 32, order: 3");
  replace("dt: 0.005 s", "dt: 0.00125 s");
  replace("steps: 600", "steps: 2400");
  const std::filesystem::path file =
      scratch("ex8-moordyn-" + std::to_string(getpid())) / "ex8-moordyn.yaml";
  std::ofstream(file) << text;
  const std::vector<double> d = differences(buoyFromSummary(runWithoutFigures(file.string())));
  const double tolerance[] = {5e-5, 5e-5, 5e-5, 5e-5, 5e-4, 3e-3};
  for (size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(d[i], 0.0, tolerance[i]) << kBuoyFields[i];
    std::cout << "[ MoorDyn ] " << kBuoyFields[i] << ": " << d[i] << "\n";
  }
}

// The named case (4 L3, the dissertation's conventions): within its conventions' share.
TEST(MoorDynComparison, Example8NamedCaseIsNearMoorDynsPath) {
  const std::vector<double> d =
      differences(buoyFromSummary(runWithoutFigures("ex8-relaxation-test")));
  const double tolerance[] = {2e-3, 1.2e-3, 8e-3, 1.2e-3, 5e-3, 5e-2};
  for (size_t i = 0; i < d.size(); ++i) {
    EXPECT_NEAR(d[i], 0.0, tolerance[i]) << kBuoyFields[i];
    std::cout << "[ MoorDyn ] " << kBuoyFields[i] << ": " << d[i] << "\n";
  }
}

}  // namespace
}  // namespace flexmoor::test
