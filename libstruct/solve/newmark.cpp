#include "libstruct/solve/newmark.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {
namespace {

using Eigen::VectorXd;

// Writes the free-dof values into a nodal field, leaving the constrained dofs as they are.
void setFree(const model::Model& m, const VectorXd& values, model::NodalField& field) {
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int eq = m.equation(n, k); eq >= 0) field(k, n) = values(eq);
}

class NewmarkStepper {
 public:
  NewmarkStepper(const model::Model& m, const model::Assembler& a, const DynamicOptions& o)
      : model_(m), assembler_(a), o_(o) {
    gamma_ = o.gamma;
    beta_ = o.beta;
    alpha_ = o.hht_alpha;
    if (alpha_ != 0.0) {
      gamma_ = 0.5 - alpha_;
      beta_ = 0.25 * (1.0 - alpha_) * (1.0 - alpha_);
    }
    masses_ = assembler_.elementMasses(o.mass);
    assembler_.mass(m.initialState(), o.mass, M_);
  }

  // Damping force C v on the free dofs, C = rayleigh_mass M + rayleigh_stiffness K0.
  VectorXd damping(const VectorXd& v_free) const {
    VectorXd f = VectorXd::Zero(v_free.size());
    if (o_.rayleigh_mass != 0.0) f += o_.rayleigh_mass * (M_ * v_free);
    if (o_.rayleigh_stiffness != 0.0) f += o_.rayleigh_stiffness * (K0_ * v_free);
    return f;
  }

  // Advances `s` by h. Returns false (s unchanged) when Newton does not converge.
  bool step(model::State& s, double h, DynamicReport& report, IterationRecord& rec) {
    const double a0 = 1.0 / (beta_ * h * h), a1 = 1.0 / (beta_ * h), a2 = 0.5 / beta_ - 1.0;
    const VectorXd u_n = assembler_.restrictToFree(asVector(s.displacement));
    const VectorXd v_n = assembler_.restrictToFree(asVector(s.velocity));
    const VectorXd acc_n = assembler_.restrictToFree(asVector(s.acceleration));
    if (o_.rayleigh_stiffness != 0.0) {
      VectorXd F;
      assembler_.internalForce(s, F, &K0_);
    }
    VectorXd previous_balance;  // HHT: P_n - F_n - C v_n
    if (alpha_ != 0.0) previous_balance = outOfBalance(assembler_, s, nullptr).free - damping(v_n);

    model::State next = s;
    next.time = s.time + h;
    assembler_.applyPrescribed(next);
    VectorXd u = u_n;  // predictor: the displacement of the last step
    model::SparseMatrix K;
    const bool refresh_each_step =
        o_.flavour == NewtonFlavour::Full || o_.flavour == NewtonFlavour::SelfCorrective ||
        steps_since_update_ + 1 >= std::max(1, o_.stiffness_update) || h != factor_h_;
    trace_.start();
    singular_ = false;
    for (int it = 0; it <= o_.max_iterations; ++it) {
      const VectorXd acc = a0 * (u - u_n) - a1 * v_n - a2 * acc_n;           // Eq. 4.57
      const VectorXd v = v_n + h * ((1.0 - gamma_) * acc_n + gamma_ * acc);  // Eq. 4.58
      setFree(model_, u, next.displacement);
      setFree(model_, v, next.velocity);
      setFree(model_, acc, next.acceleration);
      const bool update = o_.flavour == NewtonFlavour::Full ? true : (it == 0 && refresh_each_step);
      Residual R = outOfBalance(assembler_, next, update ? &K : nullptr);
      VectorXd inertia_full;
      assembler_.inertiaForce(masses_, next, inertia_full);
      const VectorXd inertia = assembler_.restrictToFree(inertia_full);
      R.free = (1.0 + alpha_) * (R.free - damping(v)) - inertia;  // Eq. 4.63
      if (alpha_ != 0.0) R.free -= alpha_ * previous_balance;
      // The forces pass through zero twice a period, so the residual is measured against the
      // largest force seen in the run, not the instantaneous one (round-off would stall Newton).
      const double scale = std::max({R.scale, inertia_full.norm(), force_scale_});
      if (update) floor_ = R.floor * R.scale / scale;
      R.scale = scale;
      rec.residual_norm = R.relative();
      trace_.residual(rec.residual_norm);
      if (it > 0) {
        if (o_.flavour == NewtonFlavour::SelfCorrective ||  // Eq. 4.20: one solve, accepted
            converged(o_.convergence, rec.displacement_norm, rec.residual_norm, floor_)) {
          force_scale_ = R.scale;
          s = next;
          steps_since_update_ = refresh_each_step ? 0 : steps_since_update_ + 1;
          return true;
        }
      }
      if (!std::isfinite(rec.residual_norm) || it == o_.max_iterations) return false;
      if (update) {
        // Effective tangent (Eq. 4.63): (1 + alpha) (K_T + gamma / (beta h) C) + a0 M, with
        // C = a_M M + a_K K0. K_T, M and K0 are assembled on the assembler's one pattern, so the
        // sum is taken coefficient by coefficient, without a sparse merge or an allocation.
        const double c = (1.0 + alpha_) * gamma_ / (beta_ * h);
        Keff_ = K;
        Keff_.coeffs() = (1.0 + alpha_) * K.coeffs() + (a0 + c * o_.rayleigh_mass) * M_.coeffs();
        if (o_.rayleigh_stiffness != 0.0)
          Keff_.coeffs() += (c * o_.rayleigh_stiffness) * K0_.coeffs();
        if (!linear_.factorize(Keff_)) {
          singular_ = true;
          return false;
        }
        factor_h_ = h;
        ++report.tangent_updates;
      }
      const VectorXd du = linear_.solve(R.free);
      u += du;
      trace_.increment(model_, du);
      ++report.iterations;
      rec.iteration = it + 1;
      const double u_norm = u.norm();
      rec.displacement_norm = u_norm > 0.0 ? du.norm() / u_norm : du.norm();  // Eq. 5.1
    }
    return false;
  }

  // u'' at the start from equilibrium: M a = P - F - C v - M_p a_p on the free dofs, M_p a_p the
  // inertia of the prescribed supports' accelerations; zero if M is singular.
  void initialAcceleration(model::State& s) {
    assembler_.applyPrescribed(s);
    setFree(model_, VectorXd::Zero(model_.equationCount()), s.acceleration);
    VectorXd inertia_full;
    assembler_.inertiaForce(masses_, s, inertia_full);  // prescribed accelerations only
    const VectorXd rhs = outOfBalance(assembler_, s, nullptr).free -
                         assembler_.restrictToFree(inertia_full) -
                         damping(assembler_.restrictToFree(asVector(s.velocity)));
    LinearSolver mass_solver;
    if (mass_solver.factorize(M_)) setFree(model_, mass_solver.solve(rhs), s.acceleration);
  }

  // Continues from a state an earlier integration left, or starts from equilibrium: the accepted
  // u'' is kept when it was accepted under this load factor and equation of motion (so a run split
  // into steps gives the one-step result), and solved for otherwise.
  void start(model::State& s) {
    const model::MotionRecord& r = s.motion;
    const bool same = r.valid && r.load_factor == s.load_factor &&
                      r.mass_kind == static_cast<int>(o_.mass) &&
                      r.rayleigh_mass == o_.rayleigh_mass &&
                      r.rayleigh_stiffness == o_.rayleigh_stiffness && r.hht_alpha == alpha_;
    if (same) {
      force_scale_ = r.force_scale;
      assembler_.applyPrescribed(s);
    } else {
      initialAcceleration(s);
    }
  }

  // What the next integration continues from.
  model::MotionRecord record(const model::State& s) const {
    model::MotionRecord r;
    r.valid = true;
    r.load_factor = s.load_factor;
    r.mass_kind = static_cast<int>(o_.mass);
    r.rayleigh_mass = o_.rayleigh_mass;
    r.rayleigh_stiffness = o_.rayleigh_stiffness;
    r.hht_alpha = alpha_;
    r.force_scale = force_scale_;
    return r;
  }

  const NewtonTrace& trace() const { return trace_; }
  bool singular() const { return singular_; }

 private:
  const model::Model& model_;
  const model::Assembler& assembler_;
  const DynamicOptions& o_;
  double gamma_, beta_, alpha_;
  std::vector<Eigen::MatrixXd> masses_;  // element mass matrices, constant
  model::SparseMatrix M_, K0_, Keff_;    // on the assembler's pattern
  LinearSolver linear_;
  double factor_h_ = -1.0;
  int steps_since_update_ = 0;
  double force_scale_ = 0.0;  // largest force norm of the accepted steps
  double floor_ = 0.0;        // round-off floor of the residual at the last tangent
  NewtonTrace trace_;         // of the last step tried
  bool singular_ = false;     // the last step tried had a singular effective tangent
};

// Advances by h, halving on failure down to max_step_cuts levels.
void advance(NewmarkStepper& stepper, model::State& state, double h, int depth,
             const DynamicOptions& o, DynamicReport& report, const SolveLog& log,
             const std::function<void(const model::State&)>& on_step) {
  IterationRecord rec{report.steps + 1, 0, state.load_factor, 0.0, 0.0};
  if (stepper.step(state, h, report, rec)) {
    ++report.steps;
    log.report(rec);
    if (on_step) on_step(state);
    return;
  }
  if (depth >= o.max_step_cuts) {
    std::ostringstream s;
    s << "time step at t = " << state.time << " s did not converge even with dt = " << h << " s ("
      << rec.iteration << " iterations, displacement norm " << rec.displacement_norm
      << ", residual " << rec.residual_norm << "): ";
    if (stepper.singular())
      s << "the effective tangent K + M / (beta dt^2) is singular: a free dof has neither mass "
           "nor stiffness";
    else
      s << stepper.trace().diagnosis(log);
    if (stepper.trace().lost())
      s << " (a displacement running away there is a motion nothing resists: a mechanism, a "
           "slack line, or a load the structure cannot carry)";
    throw ConvergenceError(s.str(), rec);
  }
  ++report.cuts;
  std::ostringstream s;
  s << "t = " << state.time << " s: Newton failed with dt = " << h << " s, halving";
  log.say(s.str());
  advance(stepper, state, 0.5 * h, depth + 1, o, report, log, on_step);
  advance(stepper, state, 0.5 * h, depth + 1, o, report, log, on_step);
}

}  // namespace

DynamicReport integrate(const model::Assembler& assembler, model::State& state,
                        const DynamicOptions& options, const SolveLog& log,
                        const std::function<void(const model::State&)>& on_step) {
  const model::Model& m = assembler.model();
  NewmarkStepper stepper(m, assembler, options);
  DynamicReport report;
  if (options.load_factor) state.load_factor = *options.load_factor;
  stepper.start(state);
  state.motion = stepper.record(state);
  const auto accepted = [&](const model::State& s) {
    state.motion = stepper.record(s);  // s is `state`, the step just accepted
    if (on_step) on_step(s);
  };
  for (const TimeSegment& segment : options.schedule)
    for (int k = 0; k < segment.steps; ++k)
      advance(stepper, state, segment.dt, 0, options, report, log, accepted);
  return report;
}

}  // namespace flexmoor::solve
