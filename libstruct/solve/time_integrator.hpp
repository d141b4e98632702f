#pragma once
// A Newmark time integrator a caller steps (Eq. 4.55-4.63): initialise once, step(dt) with
// automatic step cutting, save and restore its state, and drive supports between steps (a
// scenario's fairlead now, a host code through the C API later). integrate() is a loop over it.
// Motion-dependent loads (load_point.hpp) enter the effective tangent with their stiffness,
// damping and added mass, so light lines in water converge at a useful step size.
#include <functional>
#include <map>
#include <utility>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"
#include "libstruct/solve/newton.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct DynamicReport {
  int steps = 0;       // accepted steps, cut sub-steps included
  int iterations = 0;  // Newton iterations over all steps
  int cuts = 0;        // how often a step was halved (adaptive steps: Newton failed)
  int rejections = 0;  // adaptive steps taken again, shorter, for their local error
  int backtracks = 0;  // Newton increments halved because they raised the residual
  int tangent_updates = 0;
  int load_matrix_updates = 0;  // evaluations of the motion-dependent loads' matrices
};

// What save() keeps and restore() puts back: the state and the integrator's own memory (how far
// the modified-Newton schedule has gone, the residual test's force scale).
struct IntegratorCheckpoint {
  model::State state;
  int steps_since_update = 0;
  double force_scale = 0.0;
  double next_step = 0.0;  // adaptive steps: the step to try next
};

// Each step's Newton iterations are the one loop of newton.hpp, over the step's residual (Eq.
// 4.63), which the integrator supplies as a NewtonProblem.
class TimeIntegrator : private NewtonProblem {
 public:
  // `assembler` and `options` must outlive the integrator.
  TimeIntegrator(const model::Assembler& assembler, const DynamicOptions& options,
                 const SolveLog& log = {});

  // Makes `s` ready to step: at options.load_factor when it is set, continuing from the
  // acceleration an earlier integration accepted under the same equation of motion
  // (state.motion), or else from u'' solved for from equilibrium.
  void start(model::State& s);
  // Advances `s` by dt, halving on failure down to options.max_step_cuts levels; `on_step` sees
  // every accepted (sub-)step. Throws ConvergenceError with `s` at the last accepted step.
  void step(model::State& s, double dt,
            const std::function<void(const model::State&)>& on_step = {});
  // The same to the time t_end, which the step's last state carries exactly (a schedule's
  // times t0 + n dt, computed, not summed: output times that select).
  void stepTo(model::State& s, double t_end,
              const std::function<void(const model::State&)>& on_step = {});

  // To the time t_end in steps of the schedule's choosing: with options.adaptive, as many
  // error-controlled steps as it takes, the last landing on t_end exactly; else stepTo.
  void advanceTo(model::State& s, double t_end,
                 const std::function<void(const model::State&)>& on_step = {});

  // Drives a constrained dof over the next step(): its displacement and velocity at the step's
  // end (interpolated linearly in time over cut sub-steps; the acceleration is the velocity's
  // change over the sub-step). Afterwards the dof follows its model history again unless driven
  // anew.
  void drive(int node, int component, double displacement, double velocity);

  // What restore() needs to go on from `s` as this integrator will. The step after a save
  // assembles and factors its tangent afresh, as the step after a restore does, so that the two
  // go on identically, to the bit.
  IntegratorCheckpoint save(const model::State& s);
  void restore(const IntegratorCheckpoint& checkpoint, model::State& s);

  const DynamicReport& report() const { return report_; }

 private:
  struct Target {
    double start_u, start_v, end_u, end_v, start_time, duration;
  };
  bool attempt(model::State& s, double h, IterationRecord& rec);
  // The step under way as a NewtonProblem (attempt): its end state's free displacements are the
  // unknowns, scratch_.u.
  void evaluate(int it, Eigen::VectorXd& R, IterateNorms& norms) override;
  bool accepts(const IterateNorms& norms) const override;
  bool increment(int it, const Eigen::VectorXd& R, Eigen::VectorXd& du) override;
  void add(const Eigen::VectorXd& du, double scale) override;
  void measure(const Eigen::VectorXd& du, IterateNorms& norms) const override;
  // The local error of the step just accepted, of size h, against its tolerance (AdaptiveSteps).
  double localError(double h) const;
  void adaptiveSteps(model::State& s, double t_end,
                     const std::function<void(const model::State&)>& on_step);
  [[noreturn]] void fail(const model::State& s, double h, const IterationRecord& rec) const;
  void setTargets(const model::State& s, double t_end);
  void advance(model::State& s, double h, int depth,
               const std::function<void(const model::State&)>& on_step);
  void applySupports(model::State& next, const model::State& previous, double h) const;
  void initialAcceleration(model::State& s);
  Eigen::VectorXd damping(const Eigen::VectorXd& v_free) const;
  // The balance P - F - F_d - C v at x on the free dofs (no inertia), with its scale and floor
  // (outOfBalance), into R; from the same sweep, the tangent K_ and the internal damping's
  // viscous_ when `tangent`, the motion loads' loads_ when `loads`.
  void balance(const model::State& x, bool tangent, bool loads, Residual& R);
  // Sets the weights in which viscous_ and loads_ take their matrices for a step of h: their
  // shares of the effective tangent (factorEffectiveTangent).
  void summedWeights(double h);
  void factorEffectiveTangent(double h);
  model::MotionRecord record(const model::State& s) const;

  const model::Model& model_;
  const model::Assembler& assembler_;
  const DynamicOptions& o_;
  SolveLog log_;
  double gamma_, beta_, alpha_;
  bool motion_loads_;                      // the model has stiff motion-dependent loads in use
  bool contact_loads_;                     // and some of them are contact (LineLoad::contact)
  std::vector<Eigen::MatrixXd> masses_;    // element mass matrices, constant
  model::SparseMatrix M_, K_, K0_, Keff_;  // on the assembler's pattern
  // The motion loads' matrices at their last update, and the internal damping's dF_d/du,
  // dF_d/du' (with K_), each summed into its `stiffness` with its effective-tangent weights.
  model::LoadMatrices loads_, viscous_;
  LinearSolver linear_;
  std::map<std::pair<int, int>, Target> targets_;  // driven dofs of the step under way
  DynamicReport report_;
  double factor_h_ = -1.0;
  double end_time_ = 0.0;  // where the step under way ends
  int steps_since_update_ = 0;
  double h_ = 0.0;            // adaptive steps: the next step to try
  double force_scale_ = 0.0;  // largest force norm of the accepted steps
  double floor_ = 0.0;        // round-off floor of the residual at the last tangent
  NewtonTrace trace_;         // of the last step tried
  // What the evaluation that accepted the last step leaves for the next step's start: its
  // balance and which of K_ / viscous_ and loads_ it computed, at `state`.
  struct Kept {
    bool valid = false, tangent = false, loads = false;
    double h = 0.0;  // the step whose weights loads_ and viscous_ were summed with
    model::State state;
    Eigen::VectorXd balance;
  } kept_;
  bool singular_ = false;  // the last step tried had a singular effective tangent
  // The step under way: its size and Newmark constants (Eq. 4.57-4.58), which matrices its
  // iterations take (attempt), and what the last evaluation took and measured against.
  struct StepSolve {
    double h = 0.0, a0 = 0.0, a1 = 0.0, a2 = 0.0;
    bool self_corrective = false, tangent_iterates = false, loads_iterate = false;
    bool loads_at_predictor = false, refresh_each_step = false;
    bool tangent = false, loads = false;  // of the last evaluation
    double scale = 0.0;                   // the last evaluation's force scale
  } step_;
  // Work space of the iterations, whose storage is reused: a Newton iteration allocates nothing.
  struct Scratch {
    BalanceScratch balance;
    Residual residual;
    Eigen::VectorXd viscous, inertia, free, acceleration, velocity, balance_here;
    Eigen::VectorXd u_n, v_n, acc_n, u, previous_balance;  // the step's start and iterate
    model::State next;                                     // the state the step goes to
    NewtonWork newton;
  } scratch_;
};

}  // namespace flexmoor::solve
