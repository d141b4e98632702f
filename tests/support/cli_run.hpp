#pragma once
// Running the flexmoor command from a test, as a user would, and reading what it leaves on disk.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace flexmoor::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout, then stderr
  std::string errors;  // stderr alone
};

// Runs `flexmoor ARGS` (the binary built with the tests) and collects its output and exit code.
CliRun flexmoor(const std::string& args);

// Runs a shell command line (`/usr/bin/python3 ...`) the same way.
CliRun command(const std::string& line);

// Width and height of a PNG from its IHDR chunk; {0, 0} when the file is not a PNG.
std::pair<uint32_t, uint32_t> pngSize(const std::filesystem::path& path);

std::string readFile(const std::filesystem::path& p);

// Each line a run printed on stdout, as the numbers on it.
std::vector<std::vector<double>> printedNumbers(const CliRun& r);

// The text of the one <case>.summary.json in `dir` (empty when there is none or several).
std::string readSummary(const std::filesystem::path& dir);

// The value of "key": NUMBER in a <case>.summary.json; NaN when absent.
double summaryValue(const std::string& json, const std::string& key);

// A fresh, empty scratch directory for one test.
std::filesystem::path scratch(const std::string& name);

// Runs a named case (`flexmoor run NAME --no-figure`: a figure costs a second of Python) into a
// scratch directory of its own for this process (ctest -j runs the checks of one case side by
// side), expects exit code 0 and returns the text of its <case>.summary.json.
std::string runNamedCase(const std::string& case_name);

// Writes `text` as NAME.yaml into a scratch directory of its own for this process, runs it
// (--no-figure), expects exit code 0 and returns the text of its <case>.summary.json.
std::string runCaseText(const std::string& name, const std::string& text);

// Writes `text` as DIR/NAME.yaml and runs it with `-o DIR` and `options` (" --no-figure"),
// whatever its exit code.
CliRun runText(const std::filesystem::path& dir, const std::string& name, const std::string& text,
               const std::string& options = "");

// A case name as a GoogleTest name: "ex1-suspended-cable-8xL2" -> "ex1_suspended_cable_8xL2".
std::string testName(std::string case_name);

// Name generator for INSTANTIATE_TEST_SUITE_P over structs with a `case_name`.
struct CaseParamName {
  template <class Info>
  std::string operator()(const Info& info) const {
    return testName(info.param.case_name);
  }
};

}  // namespace flexmoor::test
