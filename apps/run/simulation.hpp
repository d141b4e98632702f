#pragma once
// A run of a case in process: case -> model -> analysis steps in order -> result sinks. The
// flexmoor command wraps it (run_case.hpp: the files, the lock, the summary and the figure), and
// tests, studies and later the C API and the Python bindings run a case with it without the
// binary, collecting what they need through their own sinks (memory_sink.hpp).
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "apps/output/result_frame.hpp"
#include "apps/output/result_sink.hpp"
#include "apps/output/state_observer.hpp"
#include "apps/problem/case.hpp"
#include "apps/run/held_records.hpp"
#include "apps/run/run_case.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/solve_log.hpp"

namespace flexmoor::app {

// What a run leaves in memory: the state closing each finished step and its frame (pointing
// into `states`), and the summary quantities with their units.
struct SimulationResult {
  ExitCode exit_code = kSuccess;  // kSuccess or kNotConverged
  std::vector<model::State> states;
  std::vector<ResultFrame> frames;
  std::vector<std::pair<std::string, double>> summary;
  std::vector<std::pair<std::string, std::string>> units;  // of each summary value
};

class Simulation {
 public:
  // Progress goes to `log`, a step's non-convergence to `diag`. `c` must outlive the simulation;
  // a step that releases supports changes c.model while the run lasts and puts it back after.
  Simulation(const Case& c, std::ostream& log, std::ostream& diag);
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  ~Simulation();

  // Every record goes to every sink: each finished step's closing state (a stage record, but a
  // dynamic step's), a dynamic step's first state, every output_every-th accepted state (fixed
  // steps) or a state every output_interval (adaptive steps) and its last, and the last
  // converged state of a step that fails (a stage record).
  void addSink(ResultSink& sink) { sinks_.push_back(&sink); }
  // Every accepted state of every dynamic step, its first state included, goes to every observer.
  void addObserver(StateObserver& observer) { observers_.push_back(&observer); }

  // Runs the steps in order from the model's start state (Model::startState): prepare(), the
  // dynamic steps each in its own time steps, finish(). A step that does not converge ends the
  // run with kNotConverged after its last converged state went to the sinks; other failures
  // throw.
  SimulationResult run();

  // The life cycle a host program drives (run() is one such host):
  // Runs the steps before the case's first dynamic step and starts it: its first state is
  // recorded and time() is where the host's time starts. A case without a dynamic step runs to
  // its end. Throws solve::ConvergenceError when a step does not converge.
  void prepare();
  // Whether a dynamic step is under way (after prepare(), until finish()).
  bool stepping() const { return dynamic_ != nullptr; }
  // Advances the dynamic step under way to time t > time(), the last of its time steps landing
  // on t exactly: with fixed steps, in equal steps no longer than the step's dt at time() (one
  // step when t is the next time of its schedule); with adaptive steps, as the error asks. The
  // supports follow their histories (a host's coupled motions, model::CoupledMotion, as it set
  // them for this interval). Records fall on the step's output times; a host may go past the
  // case's duration. Throws solve::ConvergenceError with the state at the last converged step
  // (which restore() or finish() may follow), std::logic_error when no dynamic step is under way
  // or t is not later than time().
  void advanceTo(double t);
  // Closes the dynamic step under way at its last state (its last record), runs the steps after
  // it (a dynamic one in its own time steps) and evaluates the summary. A step that does not
  // converge ends the run with kNotConverged, as in run().
  SimulationResult finish();

  double time() const { return state_.time; }
  // The state reached (the last converged one after a failure).
  const model::State& state() const { return state_; }
  // The assembler of the model as the step under way has it (its supports released or not).
  const model::Assembler& assembler() const { return *assembler_; }

  // Everything a dynamic step under way needs to go on from where save() was called: the state,
  // the integrator's memory, the summary's series, the records' place. While a checkpoint is
  // alive the records after its time are held back from the sinks (HeldRecords), so that a
  // restore can take them back; they go on to the sinks when the checkpoint is destroyed.
  struct Checkpoint;
  // A checkpoint of the dynamic step under way (std::logic_error when none is). Going on after
  // a save is what going on after restoring it is, to the bit.
  std::shared_ptr<const Checkpoint> save();
  // Back to `checkpoint`, of this simulation's dynamic step under way; its records after the
  // checkpoint's time are dropped. std::invalid_argument for a checkpoint of another step or
  // simulation.
  void restore(const Checkpoint& checkpoint);
  // A checkpoint in a file (checkpoint_file.cpp), with `host`'s numbers (a host's own state: its
  // coupled motions), and back: restoreFile needs this case's simulation at the same dynamic
  // step (prepared), puts it where the file says and returns the host's numbers. Records written
  // after the file's time stay written; those held back are dropped. std::runtime_error naming
  // the file when it cannot be written, or read as a checkpoint of this simulation.
  void saveFile(const std::string& path, const std::vector<double>& host = {});
  // `check` sees the host's numbers before anything is restored, and may throw.
  using CheckpointHost = std::function<void(const std::vector<double>& host)>;
  std::vector<double> restoreFile(const std::string& path, const CheckpointHost& check = {});

 private:
  struct Dynamic;
  void runSteps();  // from next_ until a dynamic step starts or the case ends
  ResultFrame step(int i, model::State& state);
  ResultFrame frame(int i, std::string name, const model::State& s) const;
  // What a frame carries of the element results and reactions: nothing, the results, or the
  // inputs to compute them from (ResultFrame::pending) for a sink that completes them.
  enum class Results { None, Now, Pending };
  // The frame of state s of step i into f, reusing its storage (a step's closing frame always
  // has its results: the summary and the VTK files read them).
  void fill(int i, std::string name, const model::State& s, ResultFrame& f,
            Results results = Results::Now) const;
  ResultFrame modes(int i, const model::State& state);
  void startDynamic(int i);
  void record(const model::State& s);
  void recordBetween(double t);
  void accept(const model::State& s);
  void driveSchedule();  // the dynamic step under way in its own time steps to its end
  void endDynamic();
  void failed(const solve::ConvergenceError& e);
  void release(const StepSpec& step);
  void write(const ResultFrame& f);
  void sink(const ResultFrame& f);  // to every sink now
  // write() of a frame that is filled anew for the next record: the last sink may take its
  // contents (ResultSink::take).
  void take(ResultFrame& f);
  void flush();
  // The time of the earliest checkpoint alive (+infinity when none is).
  double heldFrom();
  std::vector<std::pair<std::string, double>> evaluate(
      const std::vector<ResultFrame>& frames,
      std::vector<std::pair<std::string, std::string>>& units) const;

  struct Released {
    int node, component;
    model::Model::Constraint held;
  };
  const Case& c_;
  std::ostream& log_;
  std::ostream& diag_;
  std::unique_ptr<model::Assembler> assembler_;  // built anew when a step releases supports
  std::vector<Released> released_;               // put back when the run ends
  std::vector<ResultSink*> sinks_;
  std::vector<StateObserver*> observers_;
  std::map<int, double> over_time_;  // summary index -> value over a dynamic step's time
  solve::SolveLog slog_;
  model::State state_;
  SimulationResult out_;
  size_t next_ = 0;  // the next step to run
  bool prepared_ = false;
  std::unique_ptr<Dynamic> dynamic_;  // the dynamic step under way
  // The time of the last record of the time axis (-infinity before the first).
  double last_record_time_ = -std::numeric_limits<double>::infinity();
  double last_sunk_time_ = -std::numeric_limits<double>::infinity();  // of the sinks' records
  HeldRecords held_;
  std::vector<std::weak_ptr<const Checkpoint>> checkpoints_;  // alive ones hold records back
};

}  // namespace flexmoor::app
