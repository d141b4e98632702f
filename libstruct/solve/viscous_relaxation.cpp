#include "libstruct/solve/viscous_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"
#include "libstruct/solve/newton.hpp"

namespace flexmoor::solve {
namespace {

// Eq. C.15 (and Eq. 5.1's displacement ratio): sqrt(sum du^2 / sum u^2) over the free dofs (|du|
// when u vanishes).
double changeRatio(const model::Assembler& assembler, const Eigen::VectorXd& du,
                   const model::NodalField& u) {
  const double u_norm = assembler.restrictToFree(asVector(u)).norm();
  return u_norm > 0.0 ? du.norm() / u_norm : du.norm();
}

// Newton (newton.hpp) on one implicit pseudo-time step of unit length (Eq. C.8-C.10):
// [K_T + K_L + C I] du = P - F(u) - C (u - u_prev), K_L the motion-dependent loads' stiffness.
// A step is solved when its residual is a tenth of the relaxation's residual tolerance (or at the
// round-off floor), by the Convergence test of every solver.
class RelaxationStep final : public NewtonProblem {
 public:
  RelaxationStep(const model::Assembler& a, const RelaxationOptions& o)
      : a_(a),
        o_(o),
        linear_(a.model().hasMotionLoads() ? MatrixKind::Unsymmetric : MatrixKind::Symmetric) {
    convergence_.use_displacement = false;
    convergence_.residual_tolerance = 0.1 * o.residual_tolerance;
  }

  // Solves the step from `previous` to `state` with damping C; false if it does not converge.
  bool run(model::State& state, const model::NodalField& previous, double C, int& iterations) {
    state_ = &state;
    previous_ = &previous;
    C_ = C;
    trace_.start();
    NewtonSettings settings;
    settings.max_iterations = o_.max_iterations;
    // No backtracking: the damping keeps a pseudo-time step's Newton where it converges, and
    // halving an increment whose residual rose on the way only slows it (Example 4's sheet: its
    // first step then fails in 30 iterations and is retried with ten times the damping).
    settings.backtracking = false;
    IterationRecord rec;
    const NewtonOutcome out = newtonSolve(*this, settings, a_.model(), trace_, rec);
    iterations += out.solves;
    return out.converged();
  }

  void evaluate(int, Eigen::VectorXd& R, IterateNorms& norms) override {
    Residual r = staticOutOfBalance(a_, *state_, &K_);
    if (K_.rows() > 0) stiffness_ = K_.diagonal().cwiseAbs().mean();
    static_residual_ = r.relative();  // P - F, before the pseudo-time damping
    r.free -= C_ * a_.restrictToFree(asVector(state_->displacement) - asVector(*previous_));
    K_.diagonal().array() += C_;  // Eq. C.10, D = C I (Eq. C.11)
    norms.residual = r.relative();
    norms.residual_floor = floor_ = r.floor;
    R.swap(r.free);
  }
  bool accepts(const IterateNorms& norms) const override { return converged(convergence_, norms); }
  bool increment(int, const Eigen::VectorXd& R, Eigen::VectorXd& du) override {
    if (!linear_.factorize(K_)) return false;
    du = linear_.solve(R);
    return du.allFinite();
  }
  void add(const Eigen::VectorXd& du, double scale) override {
    a_.addFree(du, state_->displacement, scale);
  }
  void measure(const Eigen::VectorXd& du, IterateNorms& norms) const override {
    incrementNorm(a_, du, state_->displacement, norms);
  }

  const NewtonTrace& trace() const { return trace_; }
  double stiffness() const { return stiffness_; }  // mean |K_ii| of the last tangent
  double floor() const { return floor_; }          // Residual::floor of the last tangent
  // |P - F| / S at the last iterate, the step's end once it converged: the static residual.
  double staticResidual() const { return static_residual_; }

 private:
  const model::Assembler& a_;
  const RelaxationOptions& o_;
  LinearSolver linear_;
  Convergence convergence_;
  model::SparseMatrix K_;
  NewtonTrace trace_;
  model::State* state_ = nullptr;
  const model::NodalField* previous_ = nullptr;
  double C_ = 0.0;
  double stiffness_ = 0.0;
  double floor_ = 0.0;
  double static_residual_ = 0.0;
};

// Why a pseudo-time step fails even with a raised damping.
std::string stepFailure(int step, double C, int retries, const NewtonTrace& trace, double stiffness,
                        const SolveLog& log) {
  std::ostringstream s;
  s << "viscous relaxation step " << step << " did not converge even with damping " << C
    << " (raised tenfold " << retries << " times): " << trace.diagnosis(log);
  if (C < 1e-6 * stiffness)
    s << " (the damping is negligible beside the stiffness, " << stiffness
      << " on the mean diagonal, and the motion is one no stiffness holds: a mechanism, such as "
         "a free rigid-body motion or an unloaded slack part)";
  return s.str();
}

// Why the schedule ran out of steps: the load never balanced (a mechanism), still moving, or
// settled but out of balance.
std::string notSettled(const RelaxationOptions& o, const RelaxationReport& r,
                       const LargestMove& move, const SolveLog& log) {
  std::ostringstream s;
  s << "viscous relaxation did not reach equilibrium in " << o.max_steps << " steps: ";
  if (r.residual_norm > 0.5)
    s << "the load stays unbalanced (residual " << r.residual_norm
      << " of the largest force) while the structure keeps moving (the largest change of the last "
         "step, "
      << move.value << ", at " << dofName(log, move.node, move.component)
      << "): a mechanism, a motion that no support or stiffness resists, driven by the load";
  else if (r.change_ratio >= o.tolerance)
    s << "still moving (change " << r.change_ratio << " in the last step, tolerance " << o.tolerance
      << "; the largest, " << move.value << ", at " << dofName(log, move.node, move.component)
      << "); more steps, a smaller damping or a static step after it may finish";
  else
    s << "the motion has settled (change " << r.change_ratio << ") but the residual, "
      << r.residual_norm << ", is above " << o.residual_tolerance << ": the damping, "
      << r.final_damping
      << ", holds the structure short of equilibrium; more steps, a smaller damping or a static "
         "step after it may finish";
  return s.str();
}

}  // namespace

// The damping schedule, flexmoor's reading of Eq. C.12-C.14 (partly illegible in the OCR): after
// step k, C(k+1) = mu(k) r(k) C(k) (Eq. C.12-C.13), where r is the step's displacement-change
// ratio of Eq. C.15, and mu(k+1) = gamma mu(k) (Eq. C.14) with mu(0) the initial damping factor
// and gamma the decrement coefficient. The damping therefore falls at least by 1/mu per step,
// faster as the motion dies out; gamma > 1 slows the fall in later steps. A step whose Newton
// iterations fail is retried with ten times the damping, so the schedule cannot run away. The run
// ends when Eq. C.15 is below the tolerance and the static residual below residual_tolerance (or
// its round-off floor).
RelaxationReport relax(const model::Assembler& assembler, model::State& state,
                       const RelaxationOptions& o, const SolveLog& log) {
  RelaxationReport report;
  RelaxationStep pseudo_step(assembler, o);
  LargestMove move;  // the largest change of the last step
  state.load_factor = o.load_factor;
  assembler.applyPrescribed(state);
  putAtRest(state, o.frozen_waves);
  Convergence equilibrium;
  equilibrium.use_displacement = false;
  equilibrium.residual_tolerance = o.residual_tolerance;
  double C = o.damping;
  double mu = o.initial_damping_factor;
  for (int step = 1; step <= o.max_steps; ++step) {
    const model::NodalField previous = state.displacement;
    int retries = 0;
    while (!pseudo_step.run(state, previous, C, report.iterations)) {
      state.displacement = previous;
      if (++retries > 8) {
        IterationRecord rec{step, 0, state.load_factor, report.change_ratio, report.residual_norm};
        throw ConvergenceError(
            stepFailure(step, C, retries - 1, pseudo_step.trace(), pseudo_step.stiffness(), log),
            rec);
      }
      C *= 10.0;
    }
    const Eigen::VectorXd change =
        assembler.restrictToFree(asVector(state.displacement) - asVector(previous));
    move = largestMove(assembler.model(), change);
    const double ratio = changeRatio(assembler, change, state.displacement);  // Eq. C.15
    const double residual = pseudo_step.staticResidual();
    report.steps = step;
    report.change_ratio = ratio;
    report.residual_norm = residual;
    report.final_damping = C;
    log.report({step, 0, state.load_factor, ratio, residual});
    std::ostringstream s;
    s << "relax step " << step << "  C " << C << "  change " << ratio << "  |R|/|P| " << residual;
    log.say(s.str());
    // The equilibrium, by the residual test of every solver (converged()), with the round-off
    // floor of the step's last tangent.
    IterateNorms balance;
    balance.residual = residual;
    balance.residual_floor = pseudo_step.floor();
    if (ratio < o.tolerance && converged(equilibrium, balance)) return report;
    C *= mu * ratio;    // Eq. C.12-C.13
    mu *= o.decrement;  // Eq. C.14
  }
  IterationRecord rec{report.steps, 0, state.load_factor, report.change_ratio,
                      report.residual_norm};
  throw ConvergenceError(notSettled(o, report, move, log), rec);
}

}  // namespace flexmoor::solve
