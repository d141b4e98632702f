#pragma once
// Runs a case: its analysis steps in order, each from the state the previous one left, streaming
// every finished step to netCDF and closing with summary.json.
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/case.hpp"

namespace flexmoor::app {

struct RunOptions {
  std::string output_dir = "results";
  bool vtk = true;  // write DIR/<case>-<step>.vtk for ParaView
};

enum ExitCode { kSuccess = 0, kUsage = 1, kBadInput = 2, kNotConverged = 3, kRunFailed = 4 };

struct RunOutcome {
  ExitCode exit_code = kSuccess;
  std::string netcdf_path;
  std::string summary_path;
  std::vector<std::pair<std::string, double>> summary;
};

RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log);

}  // namespace flexmoor::app
