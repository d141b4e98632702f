#include "libstruct/solve/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libstruct/solve/arc_length.hpp"
#include "libstruct/solve/bfgs.hpp"
#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"
#include "libstruct/solve/newton.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"

namespace flexmoor::solve {
namespace {

// "increment 3 of 4 (load factor 0.75) did not converge after 50 iterations: displacement norm
// ..., residual ...; WHY"
std::string failure(const StaticOptions& o, const IterationRecord& r, const std::string& what,
                    const std::string& why) {
  std::ostringstream s;
  s << "increment " << r.increment << " of " << o.increments << " (load factor " << r.load_factor
    << ") " << what << " after " << r.iteration << " iterations: displacement norm "
    << r.displacement_norm << ", residual " << r.residual_norm;
  if (!why.empty()) s << "; " << why;
  return s.str();
}

// What a failed increment most likely means: a mechanism under load when its tangent was
// singular, else, when the iterations get nowhere, a load past the largest the structure carries,
// which smaller increments cannot pass and arc-length control finds.
std::string divergence(const NewtonTrace& trace, const SolveLog& log, double converged_factor,
                       bool singular_tangent) {
  std::ostringstream s;
  s << trace.diagnosis(log);
  if (singular_tangent)
    s << " (the tangent was singular: a mechanism, a motion that no support or stiffness holds, "
         "driven by the load)";
  else if (trace.lost())
    s << " (the load may exceed what the structure carries: it was in equilibrium at load factor "
      << converged_factor << "; smaller increments, or arc-length control, which follows the "
      << "path past a limit point, tell whether it does)";
  return s.str();
}

// A straight, unstressed cable has no transverse stiffness, so the first tangent of a pretension
// step is singular. Where such a dof carries no load the correct increment is zero: a tiny
// diagonal shift (1e-10 of the mean diagonal) lets the solve go on, and the following Newton
// iterations, on the exact residual, remove its effect. A real mechanism under load still fails
// to converge and is reported.
bool factorizeRegularised(LinearSolver& linear, model::SparseMatrix& K, const SolveLog& log,
                          bool& regularised) {
  if (linear.factorize(K)) return true;
  regularised = true;
  const double shift = 1e-10 * K.diagonal().cwiseAbs().mean();
  if (!(shift > 0.0)) return false;
  K.diagonal().array() += shift;
  std::ostringstream s;
  s << "singular tangent: regularised with a diagonal shift of " << shift;
  log.say(s.str());
  return linear.factorize(K);
}

// The Newton iterations of one increment at the state's load factor (newton.hpp): the static
// residual P - F and tangent K_T (staticOutOfBalance), refreshed every iteration (full Newton) or
// every `stiffness_update` iterations (modified Newton, BFGS), regularised when singular.
class IncrementSolve final : public NewtonProblem {
 public:
  IncrementSolve(const model::Assembler& a, const StaticOptions& o, const SolveLog& log)
      : a_(a),
        o_(o),
        log_(log),
        linear_(o.pressure_load_stiffness || a.model().hasMotionLoads() ? MatrixKind::Unsymmetric
                                                                        : MatrixKind::Symmetric) {}

  // Iterates from `state` until the Convergence test holds; a self-corrective increment that
  // `carries` its residual (Eq. 4.20: one that is not the last) is accepted after one solve while
  // its residual stays acceptable(). False when the iterations end without it; throws
  // ConvergenceError on a singular tangent.
  bool run(model::State& state, bool carries, IterationRecord& rec) {
    state_ = &state;
    carries_ = carries;
    trace_.start();
    regularised_ = false;
    updates_ = 0;
    NewtonSettings settings;
    settings.max_iterations = o_.max_iterations;
    settings.single_solve = carries;
    const NewtonOutcome out = newtonSolve(*this, settings, a_.model(), trace_, rec);
    if (out.result == NewtonResult::NoIncrement)
      throw ConvergenceError(
          failure(o_, rec, "has a singular tangent",
                  "a mechanism: a free motion that no support or stiffness holds, loaded"),
          rec);
    return out.converged();
  }

  void evaluate(int it, Eigen::VectorXd& R, IterateNorms& norms) override {
    update_ =
        o_.flavour == NewtonFlavour::Full || it == 0 || it % std::max(1, o_.stiffness_update) == 0;
    Residual r = staticOutOfBalance(a_, *state_, update_ ? &K_ : nullptr);
    norms.residual = r.relative();
    if (update_) floor_ = r.floor;
    norms.residual_floor = floor_;
    R.swap(r.free);
  }
  bool accepts(const IterateNorms& norms) const override {
    return carries_ ? acceptable(norms.residual, norms.residual_floor)
                    : converged(o_.convergence, norms);
  }
  bool increment(int it, const Eigen::VectorXd& R, Eigen::VectorXd& du) override {
    if (o_.flavour == NewtonFlavour::Bfgs && it > 0) bfgs_.add(du, previous_residual_ - R);
    if (update_) {
      ++updates_;
      if (o_.pressure_load_stiffness) a_.subtractLoadStiffness(*state_, K_);
      if (!factorizeRegularised(linear_, K_, log_, regularised_)) return false;
      bfgs_.reset();
    }
    du = o_.flavour == NewtonFlavour::Bfgs ? bfgs_.apply(R, linear_) : linear_.solve(R);
    previous_residual_ = R;
    return true;
  }
  void add(const Eigen::VectorXd& du, double scale) override {
    a_.addFree(du, state_->displacement, scale);
  }
  void measure(const Eigen::VectorXd& du, IterateNorms& norms) const override {
    incrementNorm(a_, du, state_->displacement, norms);
  }
  void evaluated(const IterationRecord& rec) const override { log_.report(rec); }

  const NewtonTrace& trace() const { return trace_; }
  bool regularised() const { return regularised_; }
  int updates() const { return updates_; }

 private:
  const model::Assembler& a_;
  const StaticOptions& o_;
  const SolveLog& log_;
  LinearSolver linear_;
  model::SparseMatrix K_;
  BfgsUpdates bfgs_;
  NewtonTrace trace_;
  Eigen::VectorXd previous_residual_;
  model::State* state_ = nullptr;  // the iterate of the increment under way
  bool carries_ = false;
  bool update_ = false;  // the tangent is refreshed at this iteration
  double floor_ = 0.0;   // round-off floor of the residual at the last tangent
  bool regularised_ = false;
  int updates_ = 0;
};

}  // namespace

StaticReport solveStatic(const model::Assembler& assembler, model::State& state,
                         const StaticOptions& options, const SolveLog& log) {
  putAtRest(state, options.frozen_waves);
  if (options.control == LoadControl::ArcLength)
    return solveArcLength(assembler, state, options, log);
  StaticReport report;
  IncrementSolve solve(assembler, options, log);
  const double start = state.load_factor;
  for (int inc = 1; inc <= options.increments; ++inc) {
    const model::State converged_state = state;
    state.load_factor = start + (options.load_factor - start) * inc / options.increments;
    assembler.applyPrescribed(state);
    putAtRest(state, options.frozen_waves);
    IterationRecord rec{inc, 0, state.load_factor, 0.0, 0.0};
    const bool carries =
        options.flavour == NewtonFlavour::SelfCorrective && inc < options.increments;
    bool done = false;
    try {
      done = solve.run(state, carries, rec);
    } catch (const ConvergenceError&) {
      state = converged_state;
      throw;
    }
    std::string how;
    if (!done) {
      // Newton got nowhere from this start (a slack cable starting straight, a line that must
      // first find the seabed): viscous relaxation (Appendix C) from the same start, its damping
      // at first the tangent's mean diagonal and falling as the motion settles, then Newton's
      // iterations to the Convergence test.
      const NewtonTrace newton = solve.trace();
      const IterationRecord newton_rec = rec;
      const bool newton_singular = solve.regularised();
      std::ostringstream s;
      s << "increment " << inc << ": Newton did not converge in " << rec.iteration
        << " iterations (residual " << rec.residual_norm
        << "); relaxing from the start instead (viscous relaxation, then Newton)";
      log.say(s.str());
      state = converged_state;
      RelaxationOptions relaxation;
      relaxation.load_factor = newton_rec.load_factor;
      relaxation.frozen_waves = options.frozen_waves;
      relaxation.residual_tolerance = std::max(options.convergence.residual_tolerance, 1e-8);
      {
        model::State start = state;
        start.load_factor = relaxation.load_factor;
        assembler.applyPrescribed(start);
        model::SparseMatrix K;
        staticOutOfBalance(assembler, start, &K);
        relaxation.damping = K.rows() > 0 ? K.diagonal().cwiseAbs().mean() : 1.0;
      }
      try {
        const RelaxationReport relaxed = relax(assembler, state, relaxation, log);
        rec = {inc, 0, state.load_factor, 0.0, 0.0};
        done = solve.run(state, false, rec);
        how = " after " + std::to_string(relaxed.steps) + " steps of viscous relaxation";
      } catch (const ConvergenceError& e) {
        state = converged_state;
        throw ConvergenceError(
            failure(options, newton_rec, "did not converge",
                    divergence(newton, log, converged_state.load_factor, newton_singular) +
                        "; viscous relaxation from the start did not settle either (" + e.what() +
                        ")"),
            newton_rec);
      }
      if (!done) {
        state = converged_state;
        throw ConvergenceError(
            failure(options, newton_rec, "did not converge",
                    divergence(newton, log, converged_state.load_factor, newton_singular) +
                        "; viscous relaxation from the start ended where Newton did not "
                        "converge either (" +
                        solve.trace().diagnosis(log) + ")"),
            newton_rec);
      }
    }
    report.increments.push_back({inc, state.load_factor, rec.iteration, solve.updates(),
                                 rec.displacement_norm, rec.residual_norm});
    std::ostringstream s;
    s << "increment " << inc << "/" << options.increments << "  load factor " << state.load_factor
      << "  iterations " << rec.iteration << how << "  max|du|/L " << rec.displacement_norm
      << "  |R|/S " << rec.residual_norm;
    log.say(s.str());
  }
  return report;
}

}  // namespace flexmoor::solve
