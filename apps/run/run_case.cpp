#include "apps/run/run_case.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>

#include "apps/output/netcdf_writer.hpp"
#include "apps/output/summary_json.hpp"
#include "apps/output/summary_quantities.hpp"
#include "apps/output/vtk_writer.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/newmark.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
const double kPi = std::acos(-1.0);

// Support reactions: F - P at the constrained dofs, zero elsewhere (inertia not included).
model::NodalField reactions(const model::Model& m, const model::Assembler& a,
                            const model::State& s) {
  Eigen::VectorXd F, P;
  a.internalForce(s, F, nullptr);
  a.externalLoad(s, P);
  model::NodalField r = model::NodalField::Zero(3, m.nodeCount());
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (m.isConstrained(n, k)) r(k, n) = F(3 * n + k) - P(3 * n + k);
  return r;
}

// Everything one run shares: the model, its assembler, the writers and the log.
class Runner {
 public:
  Runner(const Case& c, const RunOptions& o, RunOutcome& out, std::ostream& log)
      : c_(c), o_(o), log_(log), assembler_(*c.model), writer_(out.netcdf_path, *c.model, c) {
    slog_.message = [&log](const std::string& s) { log << "  " << s << std::endl; };
    slog_.node_name = [&c](int n) { return "node " + std::to_string(c.node_ids[n]); };
  }

  // Runs step i from `state`; returns its closing frame. Throws ConvergenceError with `state`
  // at the last converged point.
  ResultFrame run(int i, model::State& state) {
    const StepSpec& step = c_.steps[i];
    streamed_ = false;
    switch (step.kind) {
      case StepSpec::Kind::Relax: {
        const solve::RelaxationReport r = solve::relax(assembler_, state, step.relax, slog_);
        log_ << "  relaxed in " << r.steps << " steps (" << r.iterations
             << " Newton iterations), change " << r.change_ratio << ", residual " << r.residual_norm
             << "\n";
        break;
      }
      case StepSpec::Kind::Static: {
        const solve::StaticReport r = solve::solveStatic(assembler_, state, step.statics, slog_);
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
    f.elements = assembler_.elementResults(s);
    f.reactions = reactions(*c_.model, assembler_, s);
    return f;
  }

  void write(const ResultFrame& f) { writer_.write(f); }
  // True when the last step (a dynamic one) already wrote its closing state while streaming.
  bool streamed() const { return streamed_; }

  void vtk(const ResultFrame& f, int i) const {
    if (!o_.vtk) return;
    const fs::path path =
        fs::path(o_.output_dir) / (c_.name + "-" + std::to_string(i + 1) + ".vtk");
    writeVtk(path.string(), *c_.model, f);
  }

 private:
  ResultFrame modes(int i, const model::State& state) {
    const solve::ModalResult r = solve::naturalModes(assembler_, state, c_.steps[i].modes, slog_);
    ResultFrame f = frame(i, c_.steps[i].name, state);
    f.frequencies = r.omega;
    f.mode_shapes = r.shapes;
    log_ << "  mode   omega (rad/s)   f (Hz)      period (s)\n";
    for (size_t k = 0; k < r.omega.size(); ++k)
      log_ << "  " << std::setw(4) << k + 1 << "   " << std::setw(13) << r.omega[k] << "   "
           << std::setw(9) << r.omega[k] / (2.0 * kPi) << "   " << 2.0 * kPi / r.omega[k] << "\n";
    return f;
  }

  // Streams every output_every-th accepted state; progress every tenth of the duration.
  ResultFrame dynamic(int i, model::State& state) {
    const StepSpec& step = c_.steps[i];
    double duration = 0.0;
    for (const auto& seg : step.dynamic.schedule) duration += seg.dt * seg.steps;
    const double start = state.time, end = start + duration;
    int accepted = 0;
    double next_report = start + 0.1 * duration;
    auto on_step = [&](const model::State& s) {
      ++accepted;
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
    const solve::DynamicReport r =
        solve::integrate(assembler_, state, step.dynamic, slog_, on_step);
    log_ << "  " << r.steps << " time steps, " << r.iterations << " Newton iterations, "
         << r.tangent_updates << " tangent updates, " << r.cuts << " step cuts\n";
    streamed_ = true;
    return frame(i, step.name, state);
  }

  const Case& c_;
  const RunOptions& o_;
  std::ostream& log_;
  model::Assembler assembler_;
  NetcdfWriter writer_;
  solve::SolveLog slog_;
  bool streamed_ = false;
};

std::vector<std::pair<std::string, double>> evaluate(
    const Case& c, const std::vector<ResultFrame>& frames,
    std::vector<std::pair<std::string, std::string>>& units) {
  std::vector<std::pair<std::string, double>> values;
  for (const SummarySpec& spec : c.summary) {
    const int step = spec.step < 0 ? static_cast<int>(c.steps.size()) - 1 : spec.step;
    if (step >= static_cast<int>(frames.size())) continue;  // that step never finished
    values.emplace_back(spec.name, evaluateSummary(spec, *c.model, frames[step]));
    units.emplace_back(spec.name, spec.unit);
  }
  return values;
}

}  // namespace

RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log) {
  fs::create_directories(options.output_dir);
  RunOutcome out;
  out.netcdf_path = (fs::path(options.output_dir) / (c.name + ".nc")).string();
  out.summary_path = (fs::path(options.output_dir) / "summary.json").string();

  const model::Model& m = *c.model;
  Runner runner(c, options, out, log);
  log << "flexmoor: case " << c.name << " (" << c.file << ")\n  " << m.nodeCount() << " nodes, "
      << m.elementCount() << " elements, " << m.equationCount() << " equations, " << c.steps.size()
      << " steps\n";

  std::vector<model::State> states;  // the state closing each step; frames point into it
  states.reserve(c.steps.size());
  std::vector<ResultFrame> frames;
  model::State state = m.initialState();
  for (size_t i = 0; i < c.steps.size(); ++i) {
    const StepSpec& step = c.steps[i];
    log << "step " << i + 1 << "/" << c.steps.size() << ": " << step.name << std::endl;
    try {
      ResultFrame f = runner.run(static_cast<int>(i), state);
      states.push_back(state);
      f.state = &states.back();
      frames.push_back(std::move(f));
    } catch (const solve::ConvergenceError& e) {
      log << "flexmoor: step " << i + 1 << " (" << step.name << ", " << step.where.file << ":"
          << step.where.line << ") did not converge: " << e.what() << std::endl;
      runner.write(runner.frame(static_cast<int>(i), step.name + " (last converged)", state));
      log << "  last converged state written to " << out.netcdf_path << "\n";
      out.exit_code = kNotConverged;
      break;
    }
    if (!runner.streamed()) runner.write(frames.back());
    runner.vtk(frames.back(), static_cast<int>(i));
  }

  std::vector<std::pair<std::string, std::string>> units;
  out.summary = evaluate(c, frames, units);
  writeSummaryJson(out.summary_path, c.name, out.summary, units);
  log << "summary (" << unitNames(c.units).length << ", " << unitNames(c.units).force << "):\n";
  for (size_t k = 0; k < out.summary.size(); ++k)
    log << "  " << std::left << std::setw(24) << out.summary[k].first << std::setprecision(8)
        << out.summary[k].second << " " << units[k].second << "\n";
  log << "results: " << out.netcdf_path << "\n         " << out.summary_path << "\n";
  return out;
}

}  // namespace flexmoor::app
