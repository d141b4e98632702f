#include "libstruct/solve/static_solver.hpp"

#include <cmath>
#include <sstream>

#include "libstruct/solve/arc_length.hpp"
#include "libstruct/solve/bfgs.hpp"
#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"

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

}  // namespace

StaticReport solveStatic(const model::Assembler& assembler, model::State& state,
                         const StaticOptions& options, const SolveLog& log) {
  putAtRest(state);
  if (options.control == LoadControl::ArcLength)
    return solveArcLength(assembler, state, options, log);
  StaticReport report;
  LinearSolver linear(options.pressure_load_stiffness || assembler.model().hasMotionLoads()
                          ? MatrixKind::Unsymmetric
                          : MatrixKind::Symmetric);
  model::SparseMatrix K;
  BfgsUpdates bfgs;
  double floor = 0.0;  // round-off floor of the residual at the last tangent
  const double start = state.load_factor;
  for (int inc = 1; inc <= options.increments; ++inc) {
    const model::State converged_state = state;
    state.load_factor = start + (options.load_factor - start) * inc / options.increments;
    assembler.applyPrescribed(state);
    putAtRest(state);
    IterationRecord rec{inc, 0, state.load_factor, 0.0, 0.0};
    int updates = 0;
    bool done = false;
    Eigen::VectorXd du, previous_residual;
    NewtonTrace trace;
    bool regularised = false;  // a tangent of this increment was singular
    for (int it = 0; it <= options.max_iterations; ++it) {
      const bool update = options.flavour == NewtonFlavour::Full || it == 0 ||
                          it % std::max(1, options.stiffness_update) == 0;
      const Residual R = staticOutOfBalance(assembler, state, update ? &K : nullptr);
      rec.residual_norm = R.relative();
      trace.residual(rec.residual_norm);
      if (update) floor = R.floor;
      if (options.flavour == NewtonFlavour::Bfgs && it > 0)
        bfgs.add(du, previous_residual - R.free);
      if (it > 0) log.report(rec);
      const bool self_corrective = options.flavour == NewtonFlavour::SelfCorrective;
      if (it > 0 && (self_corrective || converged(options.convergence, rec.displacement_norm,
                                                  rec.residual_norm, floor))) {
        done = true;
        break;
      }
      if (!std::isfinite(rec.residual_norm) || it == options.max_iterations) break;
      if (update) {
        ++updates;
        if (options.pressure_load_stiffness) assembler.subtractLoadStiffness(state, K);
        if (!factorizeRegularised(linear, K, log, regularised)) {
          state = converged_state;
          throw ConvergenceError(
              failure(options, rec, "has a singular tangent",
                      "a mechanism: a free motion that no support or stiffness holds, loaded"),
              rec);
        }
        bfgs.reset();
      }
      du = options.flavour == NewtonFlavour::Bfgs ? bfgs.apply(R.free, linear)
                                                  : linear.solve(R.free);
      previous_residual = R.free;
      trace.increment(assembler.model(), du);
      assembler.addFree(du, state.displacement);
      rec.iteration = it + 1;
      rec.displacement_norm = displacementNorm(assembler, du, state.displacement);
    }
    if (!done) {
      state = converged_state;
      throw ConvergenceError(
          failure(options, rec, "did not converge",
                  divergence(trace, log, converged_state.load_factor, regularised)),
          rec);
    }
    report.increments.push_back(
        {inc, state.load_factor, rec.iteration, updates, rec.displacement_norm, rec.residual_norm});
    std::ostringstream s;
    s << "increment " << inc << "/" << options.increments << "  load factor " << state.load_factor
      << "  iterations " << rec.iteration << "  |du|/|u| " << rec.displacement_norm << "  |R|/|P| "
      << rec.residual_norm;
    log.say(s.str());
  }
  return report;
}

}  // namespace flexmoor::solve
