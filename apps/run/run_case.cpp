#include "apps/run/run_case.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>

#include "apps/output/atomic_output.hpp"
#include "apps/output/netcdf_writer.hpp"
#include "apps/output/output_lock.hpp"
#include "apps/output/summary_json.hpp"
#include "apps/output/summary_quantities.hpp"
#include "apps/output/summary_series.hpp"
#include "apps/output/vtk_writer.hpp"
#include "apps/run/case_outputs.hpp"
#include "apps/run/draw_figure.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/time_integrator.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
const double kPi = std::acos(-1.0);

// Everything one run shares: the model, its assembler, the netCDF writer and the log. The values
// of the summary quantities taken over time go to `over_time` (index in c.summary -> value) as
// their dynamic steps end.
class Runner {
 public:
  Runner(const Case& c, const std::string& netcdf_path, std::ostream& log,
         std::map<int, double>& over_time)
      : c_(c),
        log_(log),
        assembler_(std::make_unique<model::Assembler>(*c.model)),
        writer_(netcdf_path, *c.model, c),
        over_time_(over_time) {
    slog_.message = [&log](const std::string& s) { log << "  " << s << std::endl; };
    slog_.node_name = [&c](int n) { return "node " + std::to_string(c.node_ids[n]); };
  }

  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;
  ~Runner() {
    for (const Released& r : released_)
      c_.model->constrain(r.node, r.component, r.held.value, r.held.history);
    if (!released_.empty()) c_.model->numberEquations();
  }

  // Runs step i from `state`; returns its closing frame. Throws ConvergenceError with `state`
  // at the last converged point.
  ResultFrame run(int i, model::State& state) {
    const StepSpec& step = c_.steps[i];
    streamed_ = false;
    release(step);
    switch (step.kind) {
      case StepSpec::Kind::Relax: {
        const solve::RelaxationReport r = solve::relax(*assembler_, state, step.relax, slog_);
        log_ << "  relaxed in " << r.steps << " steps (" << r.iterations
             << " Newton iterations), change " << r.change_ratio << ", residual " << r.residual_norm
             << "\n";
        break;
      }
      case StepSpec::Kind::Static: {
        const solve::StaticReport r = solve::solveStatic(*assembler_, state, step.statics, slog_);
        int iterations = 0;
        for (const auto& inc : r.increments) iterations += inc.iterations;
        log_ << "  equilibrium at load factor " << state.load_factor << " in "
             << r.increments.size() << " increments (" << iterations << " iterations)\n";
        break;
      }
      case StepSpec::Kind::Modes:
        return modes(i, state);
      case StepSpec::Kind::Dynamic:
        return dynamic(i, state);
    }
    return frame(i, step.name, state);
  }

  ResultFrame frame(int i, std::string name, const model::State& s) const {
    ResultFrame f;
    f.step_index = i;
    f.step_name = std::move(name);
    f.state = &s;
    f.elements = assembler_->elementResults(s);
    f.reactions = assembler_->reactions(s);
    return f;
  }

  void write(const ResultFrame& f) { writer_.write(f); }

  // Lets go of the supports the step releases: the model's equations are numbered again and the
  // assembler is built anew on them. The state keeps the released dofs' positions and velocities.
  void release(const StepSpec& step) {
    if (step.release.empty()) return;
    for (const auto& [node, component] : step.release)
      released_.push_back({node, component, c_.model->release(node, component)});
    assembler_ = std::make_unique<model::Assembler>(*c_.model);
    log_ << "  released " << step.release.size() << " dof" << (step.release.size() == 1 ? "" : "s")
         << "; " << c_.model->equationCount() << " equations\n";
  }
  // Makes every record written so far survive a kill (records are synced once a second).
  void flush() { writer_.flush(); }
  // True when the last step (a dynamic one) already wrote its closing state while streaming.
  bool streamed() const { return streamed_; }

 private:
  ResultFrame modes(int i, const model::State& state) {
    const solve::ModalResult r = solve::naturalModes(*assembler_, state, c_.steps[i].modes, slog_);
    ResultFrame f = frame(i, c_.steps[i].name, state);
    f.frequencies = r.omega;
    f.mode_shapes = r.shapes;
    log_ << "  mode   omega (rad/s)   f (Hz)      period (s)\n";
    for (size_t k = 0; k < r.omega.size(); ++k)
      log_ << "  " << std::setw(4) << k + 1 << "   " << std::setw(13) << r.omega[k] << "   "
           << std::setw(9) << r.omega[k] / (2.0 * kPi) << "   " << 2.0 * kPi / r.omega[k] << "\n";
    return f;
  }

  // Streams every output_every-th accepted state; progress every tenth of the duration. The
  // summary quantities taken over the step's time see its first state and every accepted one.
  ResultFrame dynamic(int i, model::State& state) {
    const StepSpec& step = c_.steps[i];
    const double duration = step.duration();
    const double start = state.time, end = start + duration;
    int accepted = 0;
    double next_report = start + 0.1 * duration;
    SummarySeries series(c_, i, *assembler_);
    auto on_step = [&](const model::State& s) {
      ++accepted;
      series.sample(s);
      const bool last = s.time >= end - 1e-9 * std::max(1.0, duration);
      if (accepted % step.output_every == 0 || last) {
        write(frame(i, step.name, s));
      }
      if (s.time >= next_report - 1e-12 || last) {
        log_ << "  t = " << std::setprecision(6) << s.time << " s (" << std::setprecision(3)
             << 100.0 * (s.time - start) / duration << "%), " << accepted << " steps" << std::endl;
        next_report += 0.1 * duration;
      }
    };
    solve::TimeIntegrator integrator(*assembler_, step.dynamic, slog_);
    integrator.start(state);
    series.sample(state);
    for (const solve::TimeSegment& segment : step.dynamic.schedule)
      for (int k = 0; k < segment.steps; ++k) integrator.step(state, segment.dt, on_step);
    const solve::DynamicReport& r = integrator.report();
    for (const auto& [spec, value] : series.values()) over_time_[spec] = value;
    log_ << "  " << r.steps << " time steps, " << r.iterations << " Newton iterations, "
         << r.tangent_updates << " tangent updates, " << r.cuts << " step cuts\n";
    streamed_ = true;
    return frame(i, step.name, state);
  }

  const Case& c_;
  std::ostream& log_;
  std::unique_ptr<model::Assembler> assembler_;  // built anew when a step releases supports
  struct Released {
    int node, component;
    model::Model::Constraint held;
  };
  std::vector<Released> released_;  // put back when the run ends: the case can run again
  NetcdfWriter writer_;
  std::map<int, double>& over_time_;
  solve::SolveLog slog_;
  bool streamed_ = false;
};

// Runs the steps in order, streaming to `netcdf_path`; each finished step's closing state goes
// to `states` and its frame to `frames`, the summary quantities taken over a finished step's
// time to `over_time`. Returns kNotConverged, after writing the last converged state, when a
// step does not converge.
ExitCode runSteps(const Case& c, const std::string& netcdf_path, std::ostream& log,
                  std::ostream& diag, std::vector<model::State>& states,
                  std::vector<ResultFrame>& frames, std::map<int, double>& over_time) {
  Runner runner(c, netcdf_path, log, over_time);
  model::State state = c.model->initialState();
  for (size_t i = 0; i < c.steps.size(); ++i) {
    const StepSpec& step = c.steps[i];
    log << "step " << i + 1 << "/" << c.steps.size() << ": " << step.name << std::endl;
    try {
      ResultFrame f = runner.run(static_cast<int>(i), state);
      states.push_back(state);
      f.state = &states.back();
      frames.push_back(std::move(f));
    } catch (const solve::ConvergenceError& e) {
      diag << "flexmoor: step " << i + 1 << " (" << step.name << ", " << step.where.file << ":"
           << step.where.line << ") did not converge: " << e.what() << std::endl;
      runner.write(runner.frame(static_cast<int>(i), step.name + " (last converged)", state));
      runner.flush();
      return kNotConverged;
    }
    if (!runner.streamed()) runner.write(frames.back());
    runner.flush();
  }
  return kSuccess;
}

// What a run that failed leaves: the earlier results untouched, this run's records aside.
std::string whatIsLeft(const CaseOutputs& files) {
  std::string left = "  " + files.netcdf() +
                     (fs::exists(files.netcdf()) ? " is left as the last finished run wrote it"
                                                 : " was not written");
  if (fs::exists(files.partialNetcdf()))
    left += "; the records this run wrote are in " + files.partialNetcdf();
  return left + "\n";
}

std::vector<std::pair<std::string, double>> evaluate(
    const Case& c, const std::vector<ResultFrame>& frames, const std::map<int, double>& over_time,
    std::vector<std::pair<std::string, std::string>>& units) {
  std::vector<std::pair<std::string, double>> values;
  for (size_t k = 0; k < c.summary.size(); ++k) {
    const SummarySpec& spec = c.summary[k];
    const int step = spec.step < 0 ? static_cast<int>(c.steps.size()) - 1 : spec.step;
    if (step >= static_cast<int>(frames.size())) continue;  // that step never finished
    if (spec.reduction == SummarySpec::Reduction::StepEnd)
      values.emplace_back(spec.name, evaluateSummary(spec, *c.model, frames[step]));
    else
      values.emplace_back(spec.name, over_time.at(static_cast<int>(k)));
    units.emplace_back(spec.name, spec.unit);
  }
  return values;
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

}  // namespace

RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log,
                   std::ostream& diag) {
  const CaseOutputs files(
      options.output_dir.empty() ? defaultOutputDirectory(c.name) : options.output_dir, c.name);
  RunOutcome out;
  out.netcdf_path = files.netcdf();
  out.summary_path = files.summary();
  std::vector<std::pair<std::string, std::string>> units;
  try {
    fs::create_directories(files.directory());
    const OutputLock lock(files.lock(), files.directory() + ": another run of case " + c.name +
                                            " is writing there (" + files.lock() +
                                            " is locked); this run is refused and writes "
                                            "nothing: let that one end or choose another "
                                            "directory with -o");
    const model::Model& m = *c.model;
    log << "flexmoor: case " << c.name << " (" << c.file << ")\n  " << m.nodeCount() << " nodes, "
        << m.elementCount() << " elements, " << m.equationCount() << " equations, "
        << c.steps.size() << " steps\n";
    std::vector<model::State> states;  // the state closing each step; frames point into it
    states.reserve(c.steps.size());
    std::vector<ResultFrame> frames;
    std::map<int, double> over_time;  // summary quantities taken over a dynamic step's time
    try {
      out.exit_code = runSteps(c, files.partialNetcdf(), log, diag, states, frames, over_time);
      out.summary = evaluate(c, frames, over_time, units);
      putOutputsInPlace(c, options, files, frames, out, units);
    } catch (const std::exception& e) {
      diag << "flexmoor: " << e.what() << "\n" << whatIsLeft(files);
      out.exit_code = kRunFailed;
      return out;
    }
  } catch (const std::exception& e) {  // the run was refused: nothing was written
    diag << "flexmoor: " << e.what() << "\n";
    out.exit_code = kRunFailed;
    return out;
  }
  if (out.exit_code == kNotConverged)
    diag << "  last converged state written to " << out.netcdf_path << "\n";
  log << "summary (" << unitNames(c.units).length << ", " << unitNames(c.units).force << "):\n";
  for (size_t k = 0; k < out.summary.size(); ++k)
    log << "  " << std::left << std::setw(24) << out.summary[k].first << std::setprecision(8)
        << out.summary[k].second << " " << units[k].second << "\n";
  // Drawn last, from the file in place; a figure of an earlier run that this one does not draw
  // is removed.
  std::error_code ec;
  if (c.figure && options.figure &&
      drawFigure(*c.figure, c.title.empty() ? c.name : c.title, out.netcdf_path, files.figure(),
                 diag))
    out.figure_path = files.figure();
  else
    fs::remove(files.figure(), ec);
  log << "results: " << out.netcdf_path << "\n         " << out.summary_path << "\n";
  if (!out.figure_path.empty()) log << "figure:  " << out.figure_path << "\n";
  return out;
}

}  // namespace flexmoor::app
