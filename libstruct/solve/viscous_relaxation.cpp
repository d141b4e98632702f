#include "libstruct/solve/viscous_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {
namespace {

// Newton on one implicit pseudo-time step of unit length (Eq. C.8-C.10):
// [K_T + C I] du = P - F(u) - C (u - u_prev). Returns false if it does not converge.
bool relaxationStep(const model::Assembler& assembler, model::State& state,
                    const model::NodalField& previous, double C, const RelaxationOptions& o,
                    LinearSolver& linear, int& iterations) {
  model::SparseMatrix K;
  for (int it = 0; it < o.max_iterations; ++it) {
    Residual R = outOfBalance(assembler, state, &K);
    const Eigen::VectorXd velocity =
        assembler.restrictToFree(asVector(state.displacement) - asVector(previous));
    R.free -= C * velocity;     // D u' with D = C I (Eq. C.11)
    K.diagonal().array() += C;  // Eq. C.10
    if (!linear.factorize(K)) return false;
    const Eigen::VectorXd du = linear.solve(R.free);
    if (!du.allFinite()) return false;
    assembler.addFree(du, state.displacement);
    ++iterations;
    const double change = displacementNorm(assembler, du, state.displacement);
    if (change < 1e-10 || R.relative() < 0.1 * o.residual_tolerance) return true;
  }
  return false;
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
  LinearSolver linear;
  state.load_factor = o.load_factor;
  assembler.applyPrescribed(state);
  double C = o.damping;
  double mu = o.initial_damping_factor;
  for (int step = 1; step <= o.max_steps; ++step) {
    const model::NodalField previous = state.displacement;
    int retries = 0;
    while (!relaxationStep(assembler, state, previous, C, o, linear, report.iterations)) {
      state.displacement = previous;
      C *= 10.0;
      if (++retries > 8) {
        IterationRecord rec{step, 0, state.load_factor, report.change_ratio, report.residual_norm};
        throw ConvergenceError("viscous relaxation step " + std::to_string(step) +
                                   " did not converge even with damping " + std::to_string(C),
                               rec);
      }
    }
    const Eigen::VectorXd change =
        assembler.restrictToFree(asVector(state.displacement) - asVector(previous));
    const double ratio = displacementNorm(assembler, change, state.displacement);  // Eq. C.15
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
  throw ConvergenceError(
      "viscous relaxation did not reach equilibrium in " + std::to_string(o.max_steps) + " steps",
      rec);
}

}  // namespace flexmoor::solve
