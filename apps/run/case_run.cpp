#include "apps/run/case_run.hpp"

#include <sched.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <optional>
#include <ostream>
#include <set>

#include "apps/output/atomic_output.hpp"
#include "apps/output/background_sink.hpp"
#include "apps/output/netcdf_writer.hpp"
#include "apps/output/output_lock.hpp"
#include "apps/output/summary_json.hpp"
#include "apps/output/vtk_writer.hpp"
#include "apps/run/case_outputs.hpp"
#include "apps/run/draw_figure.hpp"
#include "apps/run/simulation.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
// What a run that failed leaves: the earlier results untouched, this run's records aside.
std::string whatIsLeft(const CaseOutputs& files) {
  std::string left = "  " + files.netcdf() +
                     (fs::exists(files.netcdf()) ? " is left as the last finished run wrote it"
                                                 : " was not written");
  if (fs::exists(files.partialNetcdf()))
    left += "; the records this run wrote are in " + files.partialNetcdf();
  return left + "\n";
}

// The run ended: its VTK files and summary are written, what an earlier run left and this one
// did not write is removed, and last the netCDF is renamed into place.
void putOutputsInPlace(const Case& c, const RunOptions& options, const CaseOutputs& files,
                       const std::vector<ResultFrame>& frames, RunOutcome& out,
                       const std::vector<std::pair<std::string, std::string>>& units) {
  std::set<int> vtk_steps;
  for (size_t i = 0; options.vtk && i < frames.size(); ++i) {
    writeVtk(files.vtk(static_cast<int>(i) + 1), *c.model, frames[i]);
    vtk_steps.insert(static_cast<int>(i) + 1);
  }
  writeSummaryJson(out.summary_path, c.name, out.summary, units);
  files.removeStale(vtk_steps);
  moveIntoPlace(files.partialNetcdf(), files.netcdf());
}

// The records a run streams from its dynamic steps (time steps over output_every): a thread of
// their own pays for itself from about kBackgroundRecords of them (docs/performance.md, "Output
// cost": Example 9's 232 records cost 2 ms more with it, the demo's 40,000 save 40 ms).
constexpr long kBackgroundRecords = 1000;

// The cores this process may run on (its affinity: taskset, a container's CPU set); a writing
// thread only slows a run that has no second one.
int usableCores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return 1;
  return CPU_COUNT(&set);
}

long streamedRecords(const Case& c) {
  long records = 0;
  for (const StepSpec& step : c.steps) records += step.streamedRecords();
  return records;
}

}  // namespace

CaseRun::CaseRun(const Case& c, const RunOptions& options, std::ostream& log, std::ostream& diag)
    : c_(c),
      options_(options),
      log_(log),
      diag_(diag),
      files_(options.output_dir.empty() ? defaultOutputDirectory(c.name) : options.output_dir,
             c.name) {
  fs::create_directories(files_.directory());
  lock_.emplace(files_.lock(), files_.directory() + ": another run of case " + c.name +
                                   " is writing there (" + files_.lock() +
                                   " is locked); this run is refused and writes nothing: let that "
                                   "one end or choose another directory with -o");
  const model::Model& m = *c.model;
  log << "flexmoor: case " << c.name << " (" << c.file << ")\n  " << m.nodeCount() << " nodes, "
      << m.elementCount() << " elements, " << m.equationCount() << " equations, " << c.steps.size()
      << " steps\n";
  for (const std::string& note : c.notes) log << "  " << note << "\n";
  netcdf_.emplace(files_.partialNetcdf(), *c.model, c);
  simulation_ = std::make_unique<Simulation>(c, log, diag);
  if (options.background_writer && streamedRecords(c) >= kBackgroundRecords && usableCores() >= 2)
    background_.emplace(*netcdf_);
  simulation_->addSink(background_ ? static_cast<ResultSink&>(*background_) : *netcdf_);
  for (StateObserver* o : options.observers) simulation_->addObserver(*o);
}

CaseRun::~CaseRun() = default;

RunOutcome CaseRun::run() { return close([this] { return simulation_->run(); }); }

RunOutcome CaseRun::finish() { return close([this] { return simulation_->finish(); }); }

RunOutcome CaseRun::close(const std::function<SimulationResult()>& simulate) {
  std::optional<SimulationResult> result;
  try {
    result = simulate();
  } catch (const std::exception& e) {
    diag_ << "flexmoor: " << e.what() << "\n";
  }
  RunOutcome out;
  out.netcdf_path = files_.netcdf();
  out.summary_path = files_.summary();
  try {
    // The file is closed before it is put in place.
    background_.reset();
    netcdf_.reset();
    if (!result) throw std::runtime_error("the run failed");
    out.exit_code = result->exit_code;
    out.summary = result->summary;
    putOutputsInPlace(c_, options_, files_, result->frames, out, result->units);
  } catch (const std::exception& e) {
    if (result) diag_ << "flexmoor: " << e.what() << "\n";
    diag_ << whatIsLeft(files_);
    out.exit_code = kRunFailed;
    lock_.reset();
    return out;
  }
  lock_.reset();
  const std::vector<std::pair<std::string, std::string>>& units = result->units;
  if (out.exit_code == kNotConverged)
    diag_ << "  last converged state written to " << out.netcdf_path << "\n";
  log_ << "summary (" << unitNames(c_.units).length << ", " << unitNames(c_.units).force << "):\n";
  size_t width = 23;  // names in a column at least one blank wider than the longest
  for (const auto& [name, value] : out.summary) width = std::max(width, name.size());
  for (size_t k = 0; k < out.summary.size(); ++k)
    log_ << "  " << std::left << std::setw(static_cast<int>(width) + 1) << out.summary[k].first
         << std::setprecision(8) << out.summary[k].second << " " << units[k].second << "\n";
  // Drawn last, from the file in place; a figure of an earlier run that this one does not draw
  // is removed.
  std::error_code ec;
  if (c_.figure && options_.figure &&
      drawFigure(*c_.figure, c_.title.empty() ? c_.name : c_.title, out.netcdf_path,
                 files_.figure(), diag_))
    out.figure_path = files_.figure();
  else
    fs::remove(files_.figure(), ec);
  log_ << "results: " << out.netcdf_path << "\n         " << out.summary_path << "\n";
  if (!out.figure_path.empty()) log_ << "figure:  " << out.figure_path << "\n";
  return out;
}

}  // namespace flexmoor::app
