// The flexmoor command as a user meets it: named cases run to the published numbers, bad input
// is refused with FILE:LINE messages and exit code 2, non-convergence exits with 3 and keeps the
// last converged state on disk.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using flexmoor::test::CliRun;
using flexmoor::test::flexmoor;
using flexmoor::test::readFile;
using flexmoor::test::scratch;
using flexmoor::test::summaryValue;

// Table 1 of the dissertation (seed-tables.csv), centre sag and support movement in ft; the
// tolerance is 1.5%.
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

// What `flexmoor ARGS` prints on stdout alone, stderr discarded: diagnoses must not be in it.
std::string stdoutOf(const std::string& args) {
  FILE* pipe = popen((std::string(FLEXMOOR_BINARY) + " " + args + " 2>/dev/null").c_str(), "r");
  std::string out;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  return out;
}

void expectAll(const CliRun& r, const std::vector<std::string>& parts) {
  for (const std::string& part : parts)
    EXPECT_NE(r.output.find(part), std::string::npos) << part << " in:\n" << r.output;
}

TEST(Cli, HelpTeachesTheCommands) {
  const CliRun r = flexmoor("--help");
  EXPECT_EQ(r.exit_code, 0);
  expectAll(
      r, {"run", "check", "cases", "named case", "units: US", "relax", "static", "modes", "dynamic",
          "DIR/<case>.nc", "netCDF-4", "CF", "DIR/<case>-<n>.vtk", "DIR/<case>.summary.json",
          "results/<case>/", "Exit codes", "Examples", "COMMAND --help"});
}

// `run --help` is help, not a case named '--help'. Every command has its help.
TEST(Cli, EveryCommandHasItsOwnHelp) {
  const CliRun run = flexmoor("run --help");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  expectAll(run, {"Usage: flexmoor run [OPTIONS] CASE", "-o,--output DIR", "--no-vtk",
                  "Loads from step to step", "load_factor", "results/<case>/", "DIR/<case>.nc",
                  "Exit codes", "Examples"});
  EXPECT_EQ(run.output.find("no case file"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("no case '"), std::string::npos) << run.output;

  const CliRun check = flexmoor("check --help");
  EXPECT_EQ(check.exit_code, 0) << check.output;
  expectAll(check, {"Usage: flexmoor check [OPTIONS] CASE", "FILE:LINE", "Exit codes"});

  const CliRun cases = flexmoor("cases --help");
  EXPECT_EQ(cases.exit_code, 0) << cases.output;
  expectAll(cases, {"Usage: flexmoor cases", "title"});

  const CliRun version = flexmoor("--version");
  EXPECT_EQ(version.exit_code, 0) << version.output;
  EXPECT_EQ(version.output, std::string("flexmoor ") + FLEXMOOR_VERSION + "\n");
}

// `run -o DIR CASE` runs as `run CASE -o DIR` does. Options go anywhere after the command.
TEST(Cli, RunTakesItsOptionsBeforeOrAfterTheCase) {
  const fs::path before = scratch("options-before");
  const CliRun a = flexmoor("run -o " + before.string() + " --no-vtk ex1-suspended-cable-8xL2");
  EXPECT_EQ(a.exit_code, 0) << a.output;
  EXPECT_TRUE(fs::exists(before / "ex1-suspended-cable-8xL2.summary.json")) << a.output;
  EXPECT_TRUE(fs::exists(before / "ex1-suspended-cable-8xL2.nc")) << a.output;
  EXPECT_FALSE(fs::exists(before / "ex1-suspended-cable-8xL2-1.vtk")) << "--no-vtk";

  const fs::path after = scratch("options-after");
  const CliRun b = flexmoor("run ex1-suspended-cable-8xL2 --output " + after.string());
  EXPECT_EQ(b.exit_code, 0) << b.output;
  EXPECT_TRUE(fs::exists(after / "ex1-suspended-cable-8xL2-1.vtk")) << b.output;
}

// `cases extra` is refused. A missing, extra or unknown argument is a usage error
// (exit 1) that names it, on stderr, and runs nothing.
TEST(Cli, UsageErrorsNameTheArgumentAndExitWith1) {
  const fs::path dir = scratch("usage");
  const struct {
    std::string args, message;
  } errors[] = {
      {"", "flexmoor: expected a command: run, check, study, cases or plot"},
      {"frob", "flexmoor: expected a command: run, check, study, cases or plot (got 'frob')"},
      {"cases extra", "flexmoor cases: The following argument was not expected: extra"},
      {"check", "flexmoor check: CASE is required"},
      {"check ex1-suspended-cable-8xL2 extra",
       "flexmoor check: The following argument was not expected: extra"},
      {"run", "flexmoor run: CASE is required"},
      {"run ex1-suspended-cable-8xL2 ex1-suspended-cable-4xL3 -o " + dir.string(),
       "flexmoor run: The following argument was not expected: ex1-suspended-cable-4xL3"},
      {"run ex1-suspended-cable-8xL2 --frob -o " + dir.string(),
       "flexmoor run: The following argument was not expected: --frob"},
      {"run ex1-suspended-cable-8xL2 -o", "flexmoor run: --output: 1 required DIR missing"},
  };
  for (const auto& e : errors) {
    const CliRun r = flexmoor(e.args);
    EXPECT_EQ(r.exit_code, 1) << e.args << "\n" << r.output;
    EXPECT_NE(r.output.find(e.message), std::string::npos) << e.args << "\n" << r.output;
    EXPECT_NE(r.output.find("--help'."), std::string::npos) << e.args << "\n" << r.output;
    EXPECT_EQ(stdoutOf(e.args), "") << e.args;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "a usage error runs nothing";
}

// A 1 KB file of nested aliases would keep `check` busy for minutes. It is refused at the
// expansion budget, on stderr, naming the line; the test only asks that it finishes. Here h is
// 10^8 scalars; a..e hold 123,460 values with their keys and lists, f alone 1,111,111, which
// passes the budget of 1,000,000 plus two per character.
TEST(Cli, AliasBombIsRefusedOnStderrAndRunsNothing) {
  const fs::path dir = scratch("bomb");
  const fs::path file = dir / "bomb.yaml";
  std::ofstream(file) << "units: SI\n"
                         "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n"
                         "b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
                         "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\n"
                         "d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
                         "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\n"
                         "f: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]\n"
                         "g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f, *f]\n"
                         "h: &h [*g, *g, *g, *g, *g, *g, *g, *g, *g, *g]\n"
                         "supports: [{nodes: *h, fix: [x]}]\n"
                         "steps: [{static: {}}]\n";
  for (const std::string& args :
       {"check " + file.string(), "run " + file.string() + " -o " + dir.string()}) {
    const CliRun r = flexmoor(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("bomb.yaml:7: f: YAML aliases expand to more than 100"),
              std::string::npos)
        << args << "\n"
        << r.output;
    EXPECT_EQ(stdoutOf(args), "") << args;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1)
      << "only the case file itself";
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

}  // namespace
