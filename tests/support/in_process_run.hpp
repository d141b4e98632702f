#pragma once
// A case from its text, run in process (apps/run/simulation.hpp): its exit code, summary and log.
#include <string>
#include <utility>
#include <vector>

#include "apps/run/simulation.hpp"

namespace flexmoor::test {

struct InProcessRun {
  app::ExitCode exit_code = app::kSuccess;
  std::vector<std::pair<std::string, double>> summary;
  std::string log;  // progress and diagnoses
  // The summary value `key`; a test failure (and 0) when there is none.
  double value(const std::string& key) const;
};

// Writes `text` as NAME.yaml to the scratch directory, reads it and runs it.
InProcessRun runCaseInProcess(const std::string& name, const std::string& text);

}  // namespace flexmoor::test
