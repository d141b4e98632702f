#include "libstruct/solve/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"
#include "libstruct/solve/newton.hpp"

namespace flexmoor::solve {
namespace {

using Eigen::VectorXd;

// One arc-length increment (Crisfield): the predictor along the tangent, then Newton's
// corrections (newton.hpp), each the residual's solution plus the multiple of the tangent
// solution K dut = P that keeps |du|^2 + psi^2 dlambda^2 |P|^2 = ds^2.
class ArcLengthPath final : public NewtonProblem {
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
    state_ = &state;
    u0_ = a_.restrictToFree(asVector(state.displacement));
    lambda0_ = state.load_factor;
    Residual start = staticOutOfBalance(a_, state, &K_);
    if (!std::isfinite(start.relative()) || !tangentSolve(state)) return false;
    const double p2 = o_.arc.psi * o_.arc.psi * P_.squaredNorm();
    const double scale = std::sqrt(dut_.squaredNorm() + p2);
    if (ds <= 0.0) ds = std::abs(o_.load_factor - state.load_factor) / o_.increments * scale;
    ds_ = ds;
    int direction = sign;
    if (previous) direction = previous->dot(dut_) >= 0.0 ? 1 : -1;
    dlambda_ = direction * ds / scale;
    du_total_ = dlambda_ * dut_;
    apply();
    trace_.start();
    trace_.increment(a_.model(), du_total_);
    NewtonSettings settings;
    settings.max_iterations = o_.max_iterations;
    settings.backtracking = false;
    const NewtonOutcome out = newtonSolve(*this, settings, a_.model(), trace_, rec);
    rec.load_factor = state.load_factor;
    du_total = du_total_;
    dlambda = dlambda_;
    return out.converged();
  }

  void evaluate(int, VectorXd& R, IterateNorms& norms) override {
    Residual r = staticOutOfBalance(a_, *state_, &K_);
    norms.residual = r.relative();
    norms.residual_floor = r.floor;
    R.swap(r.free);
  }
  bool accepts(const IterateNorms& norms) const override {
    return converged(o_.convergence, norms);
  }
  bool increment(int, const VectorXd& R, VectorXd& du) override {
    if (!tangentSolve(*state_)) return false;
    const VectorXd duR = linear_.solve(R);
    // |du_total + duR + x dut|^2 + psi^2 (dlambda + x)^2 |P|^2 = ds^2
    const double psi2 = o_.arc.psi * o_.arc.psi * P_.squaredNorm();
    const VectorXd base = du_total_ + duR;
    const double qa = dut_.squaredNorm() + psi2;
    const double qb = 2.0 * dut_.dot(base) + 2.0 * psi2 * dlambda_;
    const double qc = base.squaredNorm() + psi2 * dlambda_ * dlambda_ - ds_ * ds_;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0 || !std::isfinite(disc)) return false;
    const double r1 = (-qb + std::sqrt(disc)) / (2.0 * qa);
    const double r2 = (-qb - std::sqrt(disc)) / (2.0 * qa);
    // the root that keeps the increment closest to its own direction
    x_ = (base + r1 * dut_).dot(du_total_) >= (base + r2 * dut_).dot(du_total_) ? r1 : r2;
    du = duR + x_ * dut_;
    return true;
  }
  void add(const VectorXd& du, double scale) override {
    du_total_ += scale * du;
    dlambda_ += scale * x_;
    apply();
  }
  void measure(const VectorXd& du, IterateNorms& norms) const override {
    incrementNorm(a_, du, state_->displacement, norms);
  }

  const NewtonTrace& trace() const { return trace_; }

 private:
  // Factorises the tangent K_ (of the last evaluation at `state`) and solves K dut = P, the
  // reference load at factor 1.
  bool tangentSolve(const model::State& state) {
    model::State unit = state;
    unit.load_factor = 1.0;
    VectorXd full;
    a_.externalLoad(unit, full);
    P_ = a_.restrictToFree(full);
    if (o_.pressure_load_stiffness) a_.subtractLoadStiffness(state, K_);
    if (!linear_.factorize(K_)) return false;
    dut_ = linear_.solve(P_);
    return dut_.allFinite();
  }

  // The iterate: u0 + du_total at load factor lambda0 + dlambda.
  void apply() {
    const VectorXd u = u0_ + du_total_;
    for (int n = 0; n < a_.model().nodeCount(); ++n)
      for (int k = 0; k < 3; ++k)
        if (const int eq = a_.model().equation(n, k); eq >= 0) state_->displacement(k, n) = u(eq);
    state_->load_factor = lambda0_ + dlambda_;
  }

  const model::Assembler& a_;
  const StaticOptions& o_;
  LinearSolver linear_;
  model::SparseMatrix K_;
  VectorXd P_, dut_;   // the reference load and the tangent's solution for it
  NewtonTrace trace_;  // of the last increment tried
  // The increment under way: its start, arc length, total so far and last correction's x.
  model::State* state_ = nullptr;
  VectorXd u0_, du_total_;
  double lambda0_ = 0.0, ds_ = 0.0, dlambda_ = 0.0, x_ = 0.0;
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
