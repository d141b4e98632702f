#pragma once
// A run of a case into its result files, stepped by its caller (the flexmoor command through
// runCase, a host program through the C API): the lock on the output directory, the netCDF
// streamed into DIR/<case>.nc.partial while the simulation goes on, and at finish() the VTK
// files, the summary, the netCDF renamed into place and the figure (run_case.hpp says what a run
// leaves when it fails).
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "apps/output/background_sink.hpp"
#include "apps/output/netcdf_writer.hpp"
#include "apps/output/output_lock.hpp"
#include "apps/problem/case.hpp"
#include "apps/run/case_outputs.hpp"
#include "apps/run/run_case.hpp"
#include "apps/run/simulation.hpp"

namespace flexmoor::app {

class CaseRun {
 public:
  // Takes the output directory's lock and opens the netCDF; throws std::runtime_error when the
  // run is refused (another run holds the lock, the directory cannot be written), before
  // writing anything. `c` must outlive the run.
  CaseRun(const Case& c, const RunOptions& options, std::ostream& log, std::ostream& diag);
  ~CaseRun();

  // Prepare, advance, save and restore through it; not run() or finish() (CaseRun's own).
  Simulation& simulation() { return *simulation_; }

  // The whole case (Simulation::run), then finish()'s files.
  RunOutcome run();
  // Closes the simulation (Simulation::finish) and writes the files; prints the summary to the
  // log. A failure to write is kRunFailed with what is left, never an exception.
  RunOutcome finish();

 private:
  // Runs `simulate` (the simulation to its end), then writes the files.
  RunOutcome close(const std::function<SimulationResult()>& simulate);
  const Case& c_;
  RunOptions options_;
  std::ostream& log_;
  std::ostream& diag_;
  CaseOutputs files_;
  std::optional<OutputLock> lock_;
  std::optional<NetcdfWriter> netcdf_;
  std::unique_ptr<Simulation> simulation_;
  // Destroyed before the file closes: it writes what is still waiting (with the simulation's
  // assembler, which completes pending results).
  std::optional<BackgroundSink> background_;
};

}  // namespace flexmoor::app
