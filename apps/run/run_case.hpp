#pragma once
// Runs a case: its analysis steps in order, each from the state the previous one left, streaming
// every finished step to netCDF and closing with the VTK files and the summary.
//
// Results are never lost: a run holds DIR/.<case>.lock (a second run of the case into DIR is
// refused), streams into DIR/<case>.nc.partial and, when it ends (exit 0, or 3 with the last
// converged state), writes its VTK files and summary and renames the netCDF into place, removing
// the VTK files of an earlier run that it did not write. A run that fails (exit 4), is refused
// or is killed leaves the earlier run's DIR/<case>.nc as it was (case_outputs.hpp names the files).
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "apps/output/state_observer.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

struct RunOptions {
  std::string output_dir;  // empty: results/<case>
  bool vtk = true;         // write DIR/<case>-<step>.vtk for ParaView
  bool figure = true;      // draw DIR/<case>.png when the case has a figure:
  // Write the netCDF records on a thread of their own while the run goes on (background_sink.hpp)
  // when the case streams a thousand records or more and the process may use two cores or more;
  // false: always in the run's thread (a study's members, which fill the cores already).
  bool background_writer = true;
  // See every accepted state of the dynamic steps (a study's series); they must outlive the run.
  std::vector<StateObserver*> observers;
};

enum ExitCode { kSuccess = 0, kUsage = 1, kBadInput = 2, kNotConverged = 3, kRunFailed = 4 };

struct RunOutcome {
  ExitCode exit_code = kSuccess;
  std::string netcdf_path;
  std::string summary_path;
  std::string figure_path;  // empty when no figure was drawn
  std::vector<std::pair<std::string, double>> summary;
};

// Progress and the summary go to `log`; diagnoses (a step that did not converge, a failure, a
// refused run) to `diag`. Returns kNotConverged or kRunFailed rather than throwing.
RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log,
                   std::ostream& diag = std::cerr);

}  // namespace flexmoor::app
