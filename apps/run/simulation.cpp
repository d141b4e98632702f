#include "apps/run/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <stdexcept>

#include "apps/output/summary_quantities.hpp"
#include "apps/output/summary_series.hpp"
#include "apps/run/record_interpolator.hpp"
#include "apps/run/simulation_checkpoint.hpp"
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

// Runs step i, which is not dynamic, from `state`; returns its closing frame. Throws
// ConvergenceError with `state` at the last converged point.
ResultFrame Simulation::step(int i, model::State& state) {
  const StepSpec& step = c_.steps[i];
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
      throw std::logic_error("Simulation::step: a dynamic step is started, not run");
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

// The dynamic step under way: its integrator, the summary quantities taken over its time, its
// records and its progress. It streams its first state (unless the time axis has a record at
// its time), then every output_every-th accepted state (fixed steps) or a state every
// output_interval (adaptive steps, on the Hermite interpolant between the steps around it:
// RecordInterpolator), and its last; progress every tenth of its duration. The summary
// quantities see its first state and every accepted one.
struct Simulation::Dynamic {
  Dynamic(int i, const StepSpec& step, const Case& c, const model::Assembler& assembler,
          const solve::SolveLog& slog, double start)
      : i(i),
        step(step),
        start(start),
        end(start + step.duration()),
        tiny(1e-9 * std::max(1.0, step.duration())),
        next_report(start + 0.1 * step.duration()),
        series(std::in_place, c, i, assembler),
        between(std::in_place, assembler),
        integrator(assembler, step.dynamic, slog) {}

  double outputTime() const { return start + output_index * step.output_interval; }
  // The schedule's segment at time t (the last one after the schedule's end): its start and dt.
  std::pair<double, double> segmentAt(double t) const {
    double segment_start = start;
    for (const solve::TimeSegment& segment : step.dynamic.schedule) {
      const double segment_end = segment_start + segment.steps * segment.dt;
      if (t < segment_end - tiny) return {segment_start, segment.dt};
      segment_start = segment_end;
    }
    const solve::TimeSegment& last = step.dynamic.schedule.back();
    return {segment_start - last.steps * last.dt, last.dt};
  }

  int i;
  const StepSpec& step;
  double start, end, tiny;
  int accepted = 0;
  double next_report;
  int output_index = 1;  // adaptive steps: the next output time is start + output_index dt_out
  Results results = Results::Now;  // of the streamed records
  // Copies of these two go into checkpoints; a restore puts them back in place.
  std::optional<SummarySeries> series;
  std::optional<RecordInterpolator> between;
  ResultFrame streamed;  // one for every record of the step: its storage is reused
  model::State interpolated;
  solve::TimeIntegrator integrator;
};

void Simulation::write(const ResultFrame& f) {
  if (!f.stage && f.state->time > heldFrom()) return held_.hold(f);
  sink(f);
}

void Simulation::sink(const ResultFrame& f) {
  if (!f.stage) last_sunk_time_ = std::max(last_sunk_time_, f.state->time);
  for (ResultSink* s : sinks_) s->write(f);
}

void Simulation::take(ResultFrame& f) {
  if (sinks_.empty()) return;
  if (!f.stage && f.state->time > heldFrom()) return held_.hold(f);
  if (!f.stage) last_sunk_time_ = std::max(last_sunk_time_, f.state->time);
  for (size_t k = 0; k + 1 < sinks_.size(); ++k) sinks_[k]->write(f);
  sinks_.back()->take(f);
}

double Simulation::heldFrom() {
  double from = std::numeric_limits<double>::infinity();
  checkpoints_.erase(std::remove_if(checkpoints_.begin(), checkpoints_.end(),
                                    [&](const std::weak_ptr<const Checkpoint>& w) {
                                      const auto cp = w.lock();
                                      if (cp) from = std::min(from, cp->integrator.state.time);
                                      return !cp;
                                    }),
                     checkpoints_.end());
  if (!held_.empty()) held_.release(from, [this](const ResultFrame& f) { sink(f); });
  return from;
}

void Simulation::record(const model::State& s) {
  Dynamic& d = *dynamic_;
  // Held records are kept whole: their results are computed now (take() decides what is held).
  const Results results =
      d.results == Results::Pending && !checkpoints_.empty() ? Results::Now : d.results;
  fill(d.i, d.step.name, s, d.streamed, results);
  take(d.streamed);
  last_record_time_ = s.time;
}

// The record at output time t between the last two accepted states (adaptive steps).
void Simulation::recordBetween(double t) {
  Dynamic& d = *dynamic_;
  d.interpolated = d.between->state(t);
  fill(d.i, d.step.name, d.interpolated, d.streamed, Results::None);
  if (d.results != Results::None) d.between->results(t, d.streamed.elements, d.streamed.reactions);
  take(d.streamed);
  last_record_time_ = t;
}

void Simulation::accept(const model::State& s) {
  Dynamic& d = *dynamic_;
  ++d.accepted;
  d.series->sample(s);
  for (StateObserver* o : observers_) o->accepted(d.i, s, *assembler_);
  const double duration = d.end - d.start;
  if (s.time >= d.next_report - 1e-12) {
    log_ << "  t = " << std::setprecision(6) << s.time << " s (" << std::setprecision(3)
         << 100.0 * (s.time - d.start) / duration << "%), " << d.accepted << " steps" << std::endl;
    while (d.next_report <= s.time + 1e-12) d.next_report += 0.1 * duration;
  }
}

void Simulation::startDynamic(int i) {
  const StepSpec& step = c_.steps[i];
  release(step);
  dynamic_ = std::make_unique<Dynamic>(i, step, c_, *assembler_, slog_, state_.time);
  Dynamic& d = *dynamic_;
  // The results of streamed records: none when no sink reads them, left to the sink when it is
  // the only one and completes them (on its own thread), else computed here.
  const bool needed = std::any_of(sinks_.begin(), sinks_.end(),
                                  [](const ResultSink* sink) { return sink->needsResults(); });
  d.results = !needed                                               ? Results::None
              : sinks_.size() == 1 && sinks_[0]->completesResults() ? Results::Pending
                                                                    : Results::Now;
  d.integrator.start(state_);
  d.series->sample(state_);
  for (StateObserver* o : observers_) o->accepted(i, state_, *assembler_);
  if (step.adaptive()) d.between->accepted(state_);
  // The step's first state starts its records, unless the time axis has its time already (a
  // dynamic step ended there): time stays strictly increasing.
  if (!(state_.time <= last_record_time_)) record(state_);
}

void Simulation::advanceTo(double t) {
  if (!dynamic_) throw std::logic_error("Simulation::advanceTo: no dynamic step under way");
  if (!(t > state_.time))
    throw std::logic_error("Simulation::advanceTo: time " + std::to_string(t) +
                           " is not later than the time reached, " + std::to_string(state_.time));
  Dynamic& d = *dynamic_;
  if (d.step.adaptive()) {
    // A record every output_interval, between the two steps around its time unless a step lands
    // on it. The summary's series sees the accepted steps only, as with fixed steps.
    d.integrator.advanceTo(state_, t, [&](const model::State& s) {
      d.between->accepted(s);
      for (; d.outputTime() < s.time - d.tiny; ++d.output_index) recordBetween(d.outputTime());
      accept(s);
      if (std::abs(s.time - d.outputTime()) <= d.tiny) {
        ++d.output_index;
        record(s);
      }
    });
    return;
  }
  // Fixed steps: every output_every-th accepted state. Each time step ends at a time computed
  // from the interval's start, so that records' times are the schedule's to the last bit.
  const auto on_step = [&](const model::State& s) {
    accept(s);
    if (d.accepted % d.step.output_every == 0) record(s);
  };
  // On the schedule's grid (the interval's ends whole numbers of its segment's dt from the
  // segment's start), its own times: t0 + n dt, as the case's run steps; else equal steps no
  // longer than its dt.
  const double from = state_.time, span = t - from;
  const auto [origin, dt] = d.segmentAt(from);
  const double first = (from - origin) / dt, last = (t - origin) / dt;
  if (std::abs(first - std::round(first)) < 1e-9 && std::abs(last - std::round(last)) < 1e-9 &&
      std::lround(last) > std::lround(first)) {
    const long end = std::lround(last);
    for (long k = std::lround(first) + 1; k <= end; ++k)
      d.integrator.stepTo(state_, k == end ? t : origin + k * dt, on_step);
    return;
  }
  const int n = std::max(1, static_cast<int>(std::ceil(span / dt - 1e-9)));
  for (int k = 1; k <= n; ++k)
    d.integrator.stepTo(state_, k == n ? t : from + span * k / n, on_step);
}

void Simulation::driveSchedule() {
  Dynamic& d = *dynamic_;
  if (d.step.adaptive()) return advanceTo(d.end);
  // Each time step ends at its segment's start plus (k + 1) dt, computed, so the records' times
  // are the schedule's to the last bit (a sum of 6,000 steps of 0.1 s is 1e-12 s off).
  double segment_start = d.start;
  for (const solve::TimeSegment& segment : d.step.dynamic.schedule) {
    for (int k = 0; k < segment.steps; ++k) advanceTo(segment_start + (k + 1) * segment.dt);
    segment_start += segment.steps * segment.dt;
  }
}

void Simulation::endDynamic() {
  Dynamic& d = *dynamic_;
  if (state_.time > last_record_time_) record(state_);  // the step's last state closes its records
  const solve::DynamicReport& r = d.integrator.report();
  for (const auto& [spec, value] : d.series->values()) over_time_[spec] = value;
  log_ << "  " << r.steps << " time steps, " << r.iterations << " Newton iterations, "
       << r.tangent_updates << " tangent updates, " << r.backtracks << " backtracks, " << r.cuts
       << " step cuts";
  if (d.step.adaptive()) log_ << ", " << r.rejections << " steps taken again for their error";
  log_ << "\n";
  ResultFrame f = frame(d.i, d.step.name, state_);
  out_.states.push_back(state_);
  f.state = &out_.states.back();
  out_.frames.push_back(std::move(f));
  dynamic_.reset();
  checkpoints_.clear();
  held_.release(std::numeric_limits<double>::infinity(), [this](const ResultFrame& f) { sink(f); });
  flush();
}

std::shared_ptr<const Simulation::Checkpoint> Simulation::save() {
  if (!dynamic_) throw std::logic_error("Simulation::save: no dynamic step under way");
  Dynamic& d = *dynamic_;
  auto cp = std::make_shared<const Checkpoint>(
      Checkpoint{this, d.i, d.integrator.save(state_), d.accepted, d.output_index, d.next_report,
                 last_record_time_, *d.series, *d.between});
  checkpoints_.push_back(cp);
  return cp;
}

void Simulation::restore(const Checkpoint& cp) {
  if (cp.simulation != this || !dynamic_ || dynamic_->i != cp.step)
    throw std::invalid_argument(
        "Simulation::restore: the checkpoint is not of this simulation's dynamic step under way");
  Dynamic& d = *dynamic_;
  d.integrator.restore(cp.integrator, state_);
  d.accepted = cp.accepted;
  d.output_index = cp.output_index;
  d.next_report = cp.next_report;
  last_record_time_ = cp.last_record_time;
  d.series.emplace(cp.series);
  d.between.emplace(cp.between);
  held_.dropAfter(state_.time);
}

void Simulation::failed(const solve::ConvergenceError& e) {
  const int i = dynamic_ ? dynamic_->i : static_cast<int>(next_) - 1;
  const StepSpec& spec = c_.steps[i];
  diag_ << "flexmoor: step " << i + 1 << " (" << spec.name << ", " << spec.where.file << ":"
        << spec.where.line << ") did not converge: " << e.what() << std::endl;
  if (dynamic_) {
    dynamic_.reset();
    checkpoints_.clear();
    held_.release(std::numeric_limits<double>::infinity(),
                  [this](const ResultFrame& f) { sink(f); });
  }
  ResultFrame last = frame(i, spec.name + std::string(kLastConvergedSuffix), state_);
  last.stage = true;  // its time may be a time record's already
  write(last);
  flush();
  out_.exit_code = kNotConverged;
  next_ = c_.steps.size();
}

void Simulation::runSteps() {
  while (!dynamic_ && next_ < c_.steps.size()) {
    const int i = static_cast<int>(next_++);
    const StepSpec& spec = c_.steps[i];
    log_ << "step " << i + 1 << "/" << c_.steps.size() << ": " << spec.name << std::endl;
    if (spec.kind == StepSpec::Kind::Dynamic) return startDynamic(i);
    ResultFrame f = step(i, state_);
    out_.states.push_back(state_);
    f.state = &out_.states.back();
    out_.frames.push_back(std::move(f));
    write(out_.frames.back());
    flush();
  }
}

void Simulation::prepare() {
  if (prepared_) throw std::logic_error("Simulation::prepare: called twice");
  prepared_ = true;
  out_.states.reserve(c_.steps.size());  // the frames point into it
  state_ = c_.model->startState();
  runSteps();
}

SimulationResult Simulation::finish() {
  try {
    if (dynamic_) endDynamic();
    runSteps();
    while (dynamic_) {
      driveSchedule();
      endDynamic();
      runSteps();
    }
  } catch (const solve::ConvergenceError& e) {
    failed(e);
  }
  out_.summary = evaluate(out_.frames, out_.units);
  return std::move(out_);
}

SimulationResult Simulation::run() {
  try {
    prepare();
    if (dynamic_) driveSchedule();
  } catch (const solve::ConvergenceError& e) {
    failed(e);
  }
  return finish();
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
    if (spec.reduction == SummarySpec::Reduction::StepEnd) {
      values.emplace_back(spec.name, evaluateSummary(spec, c_, frames[step]));
    } else if (const auto v = over_time_.find(static_cast<int>(k)); v != over_time_.end()) {
      values.emplace_back(spec.name, v->second);
    } else {
      diag_ << "flexmoor: summary \"" << spec.name << "\" (" << spec.where.file << ":"
            << spec.where.line << ") left out: the run ended before its time or window"
            << std::endl;
      continue;
    }
    units.emplace_back(spec.name, spec.unit);
  }
  return values;
}

}  // namespace flexmoor::app
