#pragma once
// Running the flexmoor command from a test, as a user would, and reading what it leaves on disk.
#include <filesystem>
#include <string>

namespace flexmoor::test {

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr
};

// Runs `flexmoor ARGS` (the binary built with the tests) and collects its output and exit code.
CliRun flexmoor(const std::string& args);

std::string readFile(const std::filesystem::path& p);

// The value of "key": NUMBER in a summary.json; NaN when absent.
double summaryValue(const std::string& json, const std::string& key);

// A fresh, empty scratch directory for one test.
std::filesystem::path scratch(const std::string& name);

}  // namespace flexmoor::test
