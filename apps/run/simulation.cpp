#include "apps/run/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "apps/output/summary_quantities.hpp"
#include "apps/output/summary_series.hpp"
#include "apps/run/record_interpolator.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/time_integrator.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

}  // namespace

Simulation::Simulation(const Case& c, std::ostream& log, std::ostream& diag)
    : c_(c), log_(log), diag_(diag), assembler_(std::make_unique<model::Assembler>(*c.model)) {
  slog_.message = [&log](const std::string& s) { log << "  " << s << std::endl; };
  slog_.node_name = [&c](int n) { return "node " + std::to_string(c.node_ids[n]); };
}

Simulation::~Simulation() {
  for (const Released& r : released_)
    c_.model->constrain(r.node, r.component, r.held.value, r.held.history);
  if (!released_.empty()) c_.model->numberEquations();
}

void Simulation::write(const ResultFrame& f) {
  for (ResultSink* sink : sinks_) sink->write(f);
}

void Simulation::take(ResultFrame& f) {
  if (sinks_.empty()) return;
  for (size_t k = 0; k + 1 < sinks_.size(); ++k) sinks_[k]->write(f);
  sinks_.back()->take(f);
}

void Simulation::flush() {
  for (ResultSink* sink : sinks_) sink->flush();
}

// Lets go of the supports the step releases: the model's equations are numbered again and the
// assembler is built anew on them. The state keeps the released dofs' positions and velocities.
void Simulation::release(const StepSpec& step) {
  if (step.release.empty()) return;
  for (const auto& [node, component] : step.release)
    released_.push_back({node, component, c_.model->release(node, component)});
  assembler_ = std::make_unique<model::Assembler>(*c_.model);
  log_ << "  released " << step.release.size() << " dof" << (step.release.size() == 1 ? "" : "s")
       << "; " << c_.model->equationCount() << " equations\n";
}

ResultFrame Simulation::frame(int i, std::string name, const model::State& s) const {
  ResultFrame f;
  fill(i, std::move(name), s, f);
  return f;
}

void Simulation::fill(int i, std::string name, const model::State& s, ResultFrame& f,
                      Results results) const {
  f.step_index = i;
  // A dynamic step's frames are records of the time axis; the others' closing frames are stage
  // records (a frame of a step that did not converge is made one by run()).
  f.stage = c_.steps[i].kind != StepSpec::Kind::Dynamic;
  f.step_name = std::move(name);
  f.state = &s;
  f.pending = nullptr;
  switch (results) {
    case Results::Now:
      assembler_->results(s, f.elements, f.reactions);
      break;
    case Results::Pending:
      assembler_->resultInputs(s, f.inputs);
      f.pending = assembler_.get();
      break;
    case Results::None:
      // What a sink left in a reused frame (ResultSink::take) is not this state's.
      f.elements.clear();
      f.reactions.resize(3, 0);
  }
}

// Runs step i from `state`; returns its closing frame. Throws ConvergenceError with `state` at
// the last converged point.
ResultFrame Simulation::step(int i, model::State& state) {
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
      log_ << "  equilibrium at load factor " << state.load_factor << " in " << r.increments.size()
           << " increments (" << iterations << " iterations)\n";
      break;
    }
    case StepSpec::Kind::Modes:
      return modes(i, state);
    case StepSpec::Kind::Dynamic:
      return dynamic(i, state);
  }
  return frame(i, step.name, state);
}

ResultFrame Simulation::modes(int i, const model::State& state) {
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

// Streams its first state (see record's condition), then every output_every-th accepted state
// (fixed steps) or a state every output_interval (adaptive steps), and the last; progress every
// tenth of the duration. The summary quantities taken over the step's time see its first state
// and every accepted one.
ResultFrame Simulation::dynamic(int i, model::State& state) {
  const StepSpec& step = c_.steps[i];
  const double duration = step.duration();
  const double start = state.time, end = start + duration;
  int accepted = 0;
  double next_report = start + 0.1 * duration;
  SummarySeries series(c_, i, *assembler_);
  ResultFrame streamed;  // one for every record of the step: its storage is reused
  // The results of streamed records: none when no sink reads them, left to the sink when it is
  // the only one and completes them (on its own thread), else computed here.
  const bool needed = std::any_of(sinks_.begin(), sinks_.end(),
                                  [](const ResultSink* sink) { return sink->needsResults(); });
  const Results results = !needed                                               ? Results::None
                          : sinks_.size() == 1 && sinks_[0]->completesResults() ? Results::Pending
                                                                                : Results::Now;
  const auto record = [&](const model::State& s) {
    fill(i, step.name, s, streamed, results);
    take(streamed);
    last_record_time_ = s.time;
  };
  const double tiny = 1e-9 * std::max(1.0, duration);
  const auto progress = [&](const model::State& s, bool last) {
    if (s.time >= next_report - 1e-12 || last) {
      log_ << "  t = " << std::setprecision(6) << s.time << " s (" << std::setprecision(3)
           << 100.0 * (s.time - start) / duration << "%), " << accepted << " steps" << std::endl;
      next_report += 0.1 * duration;
    }
  };
  const auto accept = [&](const model::State& s) {
    ++accepted;
    series.sample(s);
    for (StateObserver* o : observers_) o->accepted(i, s, *assembler_);
  };
  // Fixed steps: every output_every-th accepted state and the last.
  const auto on_step = [&](const model::State& s) {
    accept(s);
    const bool last = s.time >= end - tiny;
    if (accepted % step.output_every == 0 || last) record(s);
    progress(s, last);
  };
  // Adaptive steps: a record every output_interval, between the two steps around its time
  // (RecordInterpolator) unless a step lands on it, and the last. The summary's series sees the
  // accepted steps only, as with fixed steps: each is a converged state.
  RecordInterpolator between(*assembler_);
  model::State interpolated;
  int output_index = 1;
  const auto output_time = [&] { return start + output_index * step.output_interval; };
  const auto on_adaptive_step = [&](const model::State& s) {
    between.accepted(s);
    for (; output_time() < s.time - tiny; ++output_index) {
      interpolated = between.state(output_time());
      fill(i, step.name, interpolated, streamed, Results::None);
      if (results != Results::None)
        between.results(output_time(), streamed.elements, streamed.reactions);
      take(streamed);
      last_record_time_ = interpolated.time;
    }
    accept(s);
    const bool last = s.time >= end - tiny;
    const bool on_output = std::abs(s.time - output_time()) <= tiny;
    if (on_output) ++output_index;
    if (on_output || last) record(s);
    progress(s, last);
  };
  solve::TimeIntegrator integrator(*assembler_, step.dynamic, slog_);
  integrator.start(state);
  series.sample(state);
  for (StateObserver* o : observers_) o->accepted(i, state, *assembler_);
  // The step's first state starts its records, unless the time axis has its time already (a
  // dynamic step ended there): time stays strictly increasing.
  if (!(state.time <= last_record_time_)) record(state);
  if (step.adaptive()) {
    between.accepted(state);
    integrator.advanceTo(state, end, on_adaptive_step);
  } else {
    // Each time step ends at its segment's start plus (k + 1) dt, computed, so the records'
    // times are the schedule's to the last bit (a sum of 6,000 steps of 0.1 s is 1e-12 s off).
    double segment_start = start;
    for (const solve::TimeSegment& segment : step.dynamic.schedule) {
      for (int k = 0; k < segment.steps; ++k)
        integrator.stepTo(state, segment_start + (k + 1) * segment.dt, on_step);
      segment_start += segment.steps * segment.dt;
    }
  }
  const solve::DynamicReport& r = integrator.report();
  for (const auto& [spec, value] : series.values()) over_time_[spec] = value;
  log_ << "  " << r.steps << " time steps, " << r.iterations << " Newton iterations, "
       << r.tangent_updates << " tangent updates, " << r.backtracks << " backtracks, " << r.cuts
       << " step cuts";
  if (step.adaptive()) log_ << ", " << r.rejections << " steps taken again for their error";
  log_ << "\n";
  streamed_ = true;
  return frame(i, step.name, state);
}

SimulationResult Simulation::run() {
  SimulationResult out;
  out.states.reserve(c_.steps.size());  // the frames point into it
  model::State state = c_.model->startState();
  for (size_t i = 0; i < c_.steps.size(); ++i) {
    const StepSpec& spec = c_.steps[i];
    log_ << "step " << i + 1 << "/" << c_.steps.size() << ": " << spec.name << std::endl;
    try {
      ResultFrame f = step(static_cast<int>(i), state);
      out.states.push_back(state);
      f.state = &out.states.back();
      out.frames.push_back(std::move(f));
    } catch (const solve::ConvergenceError& e) {
      diag_ << "flexmoor: step " << i + 1 << " (" << spec.name << ", " << spec.where.file << ":"
            << spec.where.line << ") did not converge: " << e.what() << std::endl;
      ResultFrame last =
          frame(static_cast<int>(i), spec.name + std::string(kLastConvergedSuffix), state);
      last.stage = true;  // its time may be a time record's already
      write(last);
      flush();
      out.exit_code = kNotConverged;
      break;
    }
    if (!streamed_) write(out.frames.back());
    flush();
  }
  out.summary = evaluate(out.frames, out.units);
  return out;
}

// The summary quantities of the steps that finished: at a step's end from its frame, or over a
// dynamic step's time from its series.
std::vector<std::pair<std::string, double>> Simulation::evaluate(
    const std::vector<ResultFrame>& frames,
    std::vector<std::pair<std::string, std::string>>& units) const {
  std::vector<std::pair<std::string, double>> values;
  for (size_t k = 0; k < c_.summary.size(); ++k) {
    const SummarySpec& spec = c_.summary[k];
    const int step = spec.step < 0 ? static_cast<int>(c_.steps.size()) - 1 : spec.step;
    if (step >= static_cast<int>(frames.size())) continue;  // that step never finished
    if (spec.reduction == SummarySpec::Reduction::StepEnd)
      values.emplace_back(spec.name, evaluateSummary(spec, *c_.model, frames[step]));
    else
      values.emplace_back(spec.name, over_time_.at(static_cast<int>(k)));
    units.emplace_back(spec.name, spec.unit);
  }
  return values;
}

}  // namespace flexmoor::app
