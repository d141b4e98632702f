#include "libstruct/solve/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {
namespace {

using Eigen::VectorXd;

class ArcLengthPath {
 public:
  ArcLengthPath(const model::Assembler& a, const StaticOptions& o)
      : a_(a),
        o_(o),
        linear_(o.pressure_load_stiffness || a.model().hasMotionLoads() ? MatrixKind::Unsymmetric
                                                                        : MatrixKind::Symmetric) {}

  // One increment of arc length ds from the converged `state`; false if it fails (state is then
  // undefined and must be restored by the caller).
  bool increment(model::State& state, double& ds, int sign, const VectorXd* previous,
                 VectorXd& du_total, double& dlambda, IterationRecord& rec) {
    const VectorXd u0 = a_.restrictToFree(asVector(state.displacement));
    VectorXd P, dut;
    if (!tangentSolve(state, nullptr, P, dut)) return false;
    const double p2 = o_.arc.psi * o_.arc.psi * P.squaredNorm();
    const double scale = std::sqrt(dut.squaredNorm() + p2);
    if (ds <= 0.0) ds = std::abs(o_.load_factor - state.load_factor) / o_.increments * scale;
    int direction = sign;
    if (previous) direction = previous->dot(dut) >= 0.0 ? 1 : -1;
    dlambda = direction * ds / scale;
    du_total = dlambda * dut;
    const double lambda0 = state.load_factor;
    apply(state, u0, du_total, lambda0 + dlambda);
    trace_.start();
    trace_.increment(a_.model(), du_total);
    IterateNorms norms;
    for (int it = 1; it <= o_.max_iterations; ++it) {
      VectorXd R;
      const bool solved = tangentSolve(state, &R, P, dut);
      trace_.residual(residual_norm_);
      if (!solved) return false;
      rec.residual_norm = norms.residual = residual_norm_;
      norms.residual_floor = residual_floor_;
      if (it > 1 && converged(o_.convergence, norms)) return true;
      const VectorXd duR = linear_.solve(R);
      // |du_total + duR + x dut|^2 + psi^2 (dlambda + x)^2 |P|^2 = ds^2
      const double psi2 = o_.arc.psi * o_.arc.psi * P.squaredNorm();
      const VectorXd base = du_total + duR;
      const double qa = dut.squaredNorm() + psi2;
      const double qb = 2.0 * dut.dot(base) + 2.0 * psi2 * dlambda;
      const double qc = base.squaredNorm() + psi2 * dlambda * dlambda - ds * ds;
      const double disc = qb * qb - 4.0 * qa * qc;
      if (disc < 0.0 || !std::isfinite(disc)) return false;
      const double r1 = (-qb + std::sqrt(disc)) / (2.0 * qa);
      const double r2 = (-qb - std::sqrt(disc)) / (2.0 * qa);
      // the root that keeps the increment closest to its own direction
      const double x = (base + r1 * dut).dot(du_total) >= (base + r2 * dut).dot(du_total) ? r1 : r2;
      const VectorXd du = duR + x * dut;
      trace_.increment(a_.model(), du);
      du_total += du;
      dlambda += x;
      apply(state, u0, du_total, lambda0 + dlambda);
      rec.iteration = it;
      rec.load_factor = state.load_factor;
      incrementNorm(a_, du, state.displacement, norms);
      rec.displacement_norm = norms.displacement;
    }
    return false;
  }

  const NewtonTrace& trace() const { return trace_; }

 private:
  // Factorises the tangent at `state` and solves K dut = P (the reference load at factor 1);
  // with R given, also returns the residual.
  bool tangentSolve(const model::State& state, VectorXd* R, VectorXd& P, VectorXd& dut) {
    model::SparseMatrix K;
    const Residual r = staticOutOfBalance(a_, state, &K);
    residual_norm_ = r.relative();
    residual_floor_ = r.floor;
    if (!std::isfinite(residual_norm_)) return false;
    if (R) *R = r.free;
    model::State unit = state;
    unit.load_factor = 1.0;
    VectorXd full;
    a_.externalLoad(unit, full);
    P = a_.restrictToFree(full);
    if (o_.pressure_load_stiffness) a_.subtractLoadStiffness(state, K);
    if (!linear_.factorize(K)) return false;
    dut = linear_.solve(P);
    return dut.allFinite();
  }

  void apply(model::State& state, const VectorXd& u0, const VectorXd& du, double lambda) const {
    VectorXd u = u0 + du;
    for (int n = 0; n < a_.model().nodeCount(); ++n)
      for (int k = 0; k < 3; ++k)
        if (const int eq = a_.model().equation(n, k); eq >= 0) state.displacement(k, n) = u(eq);
    state.load_factor = lambda;
  }

  const model::Assembler& a_;
  const StaticOptions& o_;
  LinearSolver linear_;
  double residual_norm_ = 0.0;
  double residual_floor_ = 0.0;  // round-off floor at the last tangent (Residual::floor)
  NewtonTrace trace_;            // of the last increment tried
};

void refuseDisplacementControl(const model::Model& m, const SolveLog& log) {
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (m.isConstrained(n, k) && m.prescribed(n, k) != 0.0 && !m.motion(n, k))
        throw std::invalid_argument(
            "arc-length control follows proportional loads; a prescribed support displacement "
            "needs load control (" +
            dofName(log, n, k) + ")");
}

// Why the path stopped short of the target: it turned back at a limit point (the structure
// carries no more), or it crept on in displacement with the load factor barely rising.
std::string shortOfTarget(double target, double reached, double peak, int sign, int increments,
                          const model::NodalField& u) {
  std::ostringstream s;
  s << "arc-length path did not reach load factor " << target << " in " << increments
    << " increments: ";
  if (sign * (peak - reached) > 1e-6 * std::max(1.0, std::abs(peak)))
    s << "the load factor peaked at " << peak << " and fell to " << reached
      << ": the structure carries at most about " << peak
      << " times the reference load (a limit point), short of the target";
  else
    s << "the load factor crept to " << reached << " while the displacements grew to "
      << u.cwiseAbs().maxCoeff()
      << " (largest component): a load near or beyond what the structure carries, or a "
         "mechanism, lets the path run away in displacement; more increments or a larger first "
         "increment reach the target if it is carried";
  return s.str();
}

// Displacements past this many times the model's size mean the path has run away: the residual
// test means nothing there (its round-off floor grows with the coordinates, Residual::floor), so
// the increments "converge" with any residual, and a load the structure cannot carry would end in
// a garbage equilibrium (Example 3's tube past its limit pressure would end at 5e16 ft with exit 0).
constexpr double kRunaway = 1e3;

// The diagonal of the reference configuration's bounding box.
double modelSize(const model::Model& m) {
  if (m.nodeCount() == 0) return 0.0;
  return (m.reference().rowwise().maxCoeff() - m.reference().rowwise().minCoeff()).norm();
}

std::string runaway(double target, double reached, double peak, double displacement, double size) {
  std::ostringstream s;
  s << "arc-length path runs away: at load factor " << reached << " the displacements reach "
    << displacement << ", over " << kRunaway << " times the model's size (" << size
    << "), with the load factor never past " << peak << ": the structure cannot carry load factor "
    << target << "; the most it carries is about " << peak << " times the reference load";
  return s.str();
}

}  // namespace

StaticReport solveArcLength(const model::Assembler& assembler, model::State& state,
                            const StaticOptions& options, const SolveLog& log) {
  refuseDisplacementControl(assembler.model(), log);
  StaticReport report;
  ArcLengthPath path(assembler, options);
  const double target = options.load_factor;
  const int sign = target >= state.load_factor ? 1 : -1;
  double ds = -1.0;                 // set by the first predictor
  double peak = state.load_factor;  // the largest load factor (towards the target) on the path
  const double size = modelSize(assembler.model());
  VectorXd previous;
  for (int inc = 1; inc <= options.arc.max_increments; ++inc) {
    if (sign * (target - state.load_factor) <= 1e-12 * std::max(1.0, std::abs(target))) break;
    const model::State converged = state;
    IterationRecord rec{inc, 0, state.load_factor, 0.0, 0.0};
    VectorXd du;
    double dlambda = 0.0;
    int cuts = 0;
    while (
        !path.increment(state, ds, sign, previous.size() ? &previous : nullptr, du, dlambda, rec)) {
      state = converged;
      ds *= 0.5;
      if (++cuts > options.arc.max_cuts) {
        std::ostringstream s;
        s << "arc-length increment " << inc << " from load factor " << converged.load_factor
          << " did not converge even with arc length " << ds << " (residual " << rec.residual_norm
          << "): " << path.trace().diagnosis(log);
        throw ConvergenceError(s.str(), rec);
      }
    }
    if (sign * (state.load_factor - target) > 0.0) {
      // Past the target: land on it from the last converged state by load control.
      state = converged;
      StaticOptions last = options;
      last.control = LoadControl::Load;
      last.increments = 1;
      last.load_factor = target;
      const StaticReport landing = solveStatic(assembler, state, last, {});
      report.increments.push_back(landing.increments.back());
      report.increments.back().increment = inc;
      std::ostringstream s;
      s << "increment " << inc << "  landed on load factor " << target << " by load control";
      log.say(s.str());
      break;
    }
    const double largest = state.displacement.cwiseAbs().maxCoeff();
    if (size > 0.0 && !(largest < kRunaway * size)) {
      const double reached = state.load_factor;
      state = converged;
      throw ConvergenceError(runaway(target, reached, peak, largest, size), rec);
    }
    previous = du;
    if (sign * (state.load_factor - peak) > 0.0) peak = state.load_factor;
    report.increments.push_back({inc, state.load_factor, rec.iteration, rec.iteration,
                                 rec.displacement_norm, rec.residual_norm});
    std::ostringstream s;
    s << "increment " << inc << "  load factor " << state.load_factor << "  arc " << ds
      << "  iterations " << rec.iteration << "  |R|/|P| " << rec.residual_norm;
    log.say(s.str());
    const double growth =
        std::sqrt(double(options.arc.desired_iterations) / std::max(1, rec.iteration));
    ds *= std::clamp(growth, 1.0 / options.arc.max_growth, options.arc.max_growth);
  }
  if (sign * (target - state.load_factor) > 1e-12 * std::max(1.0, std::abs(target))) {
    IterationRecord rec{static_cast<int>(report.increments.size()), 0, state.load_factor, 0, 0};
    throw ConvergenceError(shortOfTarget(target, state.load_factor, peak, sign,
                                         options.arc.max_increments, state.displacement),
                           rec);
  }
  return report;
}

}  // namespace flexmoor::solve
