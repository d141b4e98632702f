#include "libstruct/solve/viscous_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {
namespace {

// Eq. C.15 (and Eq. 5.1's displacement ratio): sqrt(sum du^2 / sum u^2) over the free dofs (|du|
// when u vanishes).
double changeRatio(const model::Assembler& assembler, const Eigen::VectorXd& du,
                   const model::NodalField& u) {
  const double u_norm = assembler.restrictToFree(asVector(u)).norm();
  return u_norm > 0.0 ? du.norm() / u_norm : du.norm();
}

// Newton on one implicit pseudo-time step of unit length (Eq. C.8-C.10):
// [K_T + K_L + C I] du = P - F(u) - C (u - u_prev), K_L the motion-dependent loads' stiffness.
// Returns false if it does not converge.
// `trace` records the iterations; `stiffness` is set to the mean |K_ii| of the tangent.
bool relaxationStep(const model::Assembler& assembler, model::State& state,
                    const model::NodalField& previous, double C, const RelaxationOptions& o,
                    LinearSolver& linear, int& iterations, NewtonTrace& trace, double& stiffness) {
  model::SparseMatrix K;
  trace.start();
  for (int it = 0; it < o.max_iterations; ++it) {
    Residual R = staticOutOfBalance(assembler, state, &K);
    trace.residual(R.relative());
    if (K.rows() > 0) stiffness = K.diagonal().cwiseAbs().mean();
    const Eigen::VectorXd velocity =
        assembler.restrictToFree(asVector(state.displacement) - asVector(previous));
    R.free -= C * velocity;     // D u' with D = C I (Eq. C.11)
    K.diagonal().array() += C;  // Eq. C.10
    if (!linear.factorize(K)) return false;
    const Eigen::VectorXd du = linear.solve(R.free);
    trace.increment(assembler.model(), du);
    if (!du.allFinite()) return false;
    assembler.addFree(du, state.displacement);
    ++iterations;
    const double change = changeRatio(assembler, du, state.displacement);
    if (change < 1e-10 || R.relative() < 0.1 * o.residual_tolerance) return true;
  }
  return false;
}

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
// ends when Eq. C.15 is below the tolerance and the static residual below residual_tolerance.
RelaxationReport relax(const model::Assembler& assembler, model::State& state,
                       const RelaxationOptions& o, const SolveLog& log) {
  RelaxationReport report;
  LinearSolver linear(assembler.model().hasMotionLoads() ? MatrixKind::Unsymmetric
                                                         : MatrixKind::Symmetric);
  NewtonTrace trace;
  double stiffness = 0.0;
  LargestMove move;  // the largest change of the last step
  state.load_factor = o.load_factor;
  assembler.applyPrescribed(state);
  putAtRest(state, o.frozen_waves);
  double C = o.damping;
  double mu = o.initial_damping_factor;
  for (int step = 1; step <= o.max_steps; ++step) {
    const model::NodalField previous = state.displacement;
    int retries = 0;
    while (!relaxationStep(assembler, state, previous, C, o, linear, report.iterations, trace,
                           stiffness)) {
      state.displacement = previous;
      if (++retries > 8) {
        IterationRecord rec{step, 0, state.load_factor, report.change_ratio, report.residual_norm};
        throw ConvergenceError(stepFailure(step, C, retries - 1, trace, stiffness, log), rec);
      }
      C *= 10.0;
    }
    const Eigen::VectorXd change =
        assembler.restrictToFree(asVector(state.displacement) - asVector(previous));
    move = largestMove(assembler.model(), change);
    const double ratio = changeRatio(assembler, change, state.displacement);  // Eq. C.15
    const double residual = outOfBalance(assembler, state, nullptr).relative();
    report.steps = step;
    report.change_ratio = ratio;
    report.residual_norm = residual;
    report.final_damping = C;
    log.report({step, 0, state.load_factor, ratio, residual});
    std::ostringstream s;
    s << "relax step " << step << "  C " << C << "  change " << ratio << "  |R|/|P| " << residual;
    log.say(s.str());
    if (ratio < o.tolerance && residual < o.residual_tolerance) return report;
    C *= mu * ratio;    // Eq. C.12-C.13
    mu *= o.decrement;  // Eq. C.14
  }
  IterationRecord rec{report.steps, 0, state.load_factor, report.change_ratio,
                      report.residual_norm};
  throw ConvergenceError(notSettled(o, report, move, log), rec);
}

}  // namespace flexmoor::solve
