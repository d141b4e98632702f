// The flexmoor command as a user meets it: named cases run to the published numbers, bad input
// is refused with FILE:LINE messages and exit code 2, non-convergence exits with 3 and keeps the
// last converged state on disk.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using flexmoor::test::CliRun;
using flexmoor::test::flexmoor;
using flexmoor::test::readFile;
using flexmoor::test::scratch;
using flexmoor::test::summaryValue;

// Table 1 of the dissertation (seed-tables.csv), centre sag and support movement in ft; the
// issue asks for 1.5%.
struct Table1Row {
  const char* case_name;
  double sag, movement;
};
void PrintTo(const Table1Row& r, std::ostream* os) { *os << r.case_name; }

class Example1 : public ::testing::TestWithParam<Table1Row> {};

TEST_P(Example1, NamedCaseReproducesTable1Within1_5Percent) {
  const Table1Row row = GetParam();
  const fs::path dir = scratch(row.case_name);
  const CliRun r = flexmoor(std::string("run ") + row.case_name + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string json = readFile(dir / (std::string(row.case_name) + ".summary.json"));
  EXPECT_NEAR(summaryValue(json, "center_sag"), row.sag, 0.015 * row.sag) << json;
  EXPECT_NEAR(summaryValue(json, "support_movement"), row.movement, 0.015 * row.movement) << json;
  EXPECT_TRUE(fs::exists(dir / (std::string(row.case_name) + ".nc")));
  EXPECT_NE(json.find("\"center_sag\": \"ft\""), std::string::npos) << json;
}

INSTANTIATE_TEST_SUITE_P(Table1, Example1,
                         ::testing::Values(Table1Row{"ex1-suspended-cable-8xL2", 58.13, 47.68},
                                           Table1Row{"ex1-suspended-cable-4xL3", 59.25, 46.93},
                                           Table1Row{"ex1-suspended-cable-2xL4", 57.84, 46.89}),
                         flexmoor::test::CaseParamName());

TEST(Cli, HelpTeachesTheCommands) {
  const CliRun r = flexmoor("--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"run", "check", "cases", "summary.json", "Exit codes"})
    EXPECT_NE(r.output.find(word), std::string::npos) << word;
}

// Every case file shipped under cases/ is listed by `flexmoor cases` and passes `flexmoor check`
// as it stands.
TEST(Cli, EveryShippedCaseIsListedAndValid) {
  const CliRun list = flexmoor("cases");
  EXPECT_EQ(list.exit_code, 0);
  int count = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(FLEXMOOR_SOURCE_DIR) / "cases")) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const std::string name = entry.path().stem().string();
    EXPECT_NE(list.output.find(name), std::string::npos) << list.output;
    const CliRun check = flexmoor("check " + name);
    EXPECT_EQ(check.exit_code, 0) << check.output;
    EXPECT_NE(check.output.find("valid"), std::string::npos) << check.output;
  }
  EXPECT_GE(count, 3);
}

TEST(Cli, CheckValidatesWithoutRunning) {
  const fs::path dir = scratch("check");
  const CliRun r = flexmoor("check ex1-suspended-cable-8xL2");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
}

TEST(Cli, BadCaseIsRefusedWithEveryProblemAndItsLine) {
  const fs::path dir = scratch("bad");
  const fs::path file = dir / "bad.yaml";
  std::ofstream(file)
      << "name: bad\n"
         "units: US\n"
         "materials:\n"
         "  cable: {type: linear_elastic, E: -1000 psf}\n"
         "sections:\n"
         "  cable: {material: cable, area: 0.1 ft, density: 1}\n"
         "lines:\n"
         "  - {from: [0, 0, 0], to: [10, 0, 0], elements: 2, order: 7, section: cable}\n"
         "steps:\n"
         "  - static: {increments: 0}\n";
  const CliRun r = flexmoor("run " + file.string() + " -o " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("bad.yaml:4:"), std::string::npos) << r.output;   // E < 0
  EXPECT_NE(r.output.find("bad.yaml:6:"), std::string::npos) << r.output;   // area in ft
  EXPECT_NE(r.output.find("bad.yaml:8:"), std::string::npos) << r.output;   // order 7
  EXPECT_NE(r.output.find("bad.yaml:10:"), std::string::npos) << r.output;  // 0 increments
  EXPECT_FALSE(fs::exists(dir / "bad.nc")) << "nothing may run on bad input";
}

TEST(Cli, NonConvergenceExitsWith3AndKeepsTheLastConvergedState) {
  const fs::path dir = scratch("diverge");
  const fs::path file = dir / "diverge.yaml";
  std::string text =
      readFile(fs::path(FLEXMOOR_SOURCE_DIR) / "cases/seed/ex1-suspended-cable-8xL2.yaml");
  // One relaxation step cannot reach equilibrium.
  text = std::regex_replace(text, std::regex("damping: 10000\\}"), "damping: 10000, max_steps: 1}");
  text = std::regex_replace(text, std::regex("name: ex1-suspended-cable-8xL2"), "name: diverge");
  std::ofstream(file) << text;
  const CliRun r = flexmoor("run " + file.string() + " -o " + dir.string());
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("did not converge"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(dir / "diverge.nc")) << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

}  // namespace
