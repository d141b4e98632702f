#pragma once
// A run of a case in process: case -> model -> analysis steps in order -> result sinks. The
// flexmoor command wraps it (run_case.hpp: the files, the lock, the summary and the figure), and
// tests, studies and later the C API and the Python bindings run a case with it without the
// binary, collecting what they need through their own sinks (memory_sink.hpp).
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/case.hpp"
#include "apps/output/result_frame.hpp"
#include "apps/output/result_sink.hpp"
#include "apps/output/state_observer.hpp"
#include "apps/run/run_case.hpp"
#include "libstruct/model/assembler.hpp"
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
  // dynamic step's), a dynamic step's first state, every output_every-th accepted state and its
  // last, and the last converged state of a step that fails (a stage record).
  void addSink(ResultSink& sink) { sinks_.push_back(&sink); }
  // Every accepted state of every dynamic step, its first state included, goes to every observer.
  void addObserver(StateObserver& observer) { observers_.push_back(&observer); }

  // Runs the steps in order from the model's start state (Model::startState). A step that does
  // not converge ends the run with kNotConverged after its last converged state went to the
  // sinks; other failures throw.
  SimulationResult run();

 private:
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
  ResultFrame dynamic(int i, model::State& state);
  void release(const StepSpec& step);
  void write(const ResultFrame& f);
  // write() of a frame that is filled anew for the next record: the last sink may take its
  // contents (ResultSink::take).
  void take(ResultFrame& f);
  void flush();
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
  bool streamed_ = false;  // the last step (a dynamic one) wrote its closing state already
  // The time of the last record of the time axis (-infinity before the first).
  double last_record_time_ = -std::numeric_limits<double>::infinity();
};

}  // namespace flexmoor::app
