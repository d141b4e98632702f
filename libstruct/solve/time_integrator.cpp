#include "libstruct/solve/time_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/step_control.hpp"

namespace flexmoor::solve {
namespace {

using Eigen::VectorXd;

// Writes the free-dof values into a nodal field, leaving the constrained dofs as they are.
void setFree(const model::Model& m, const VectorXd& values, model::NodalField& field) {
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int eq = m.equation(n, k); eq >= 0) field(k, n) = values(eq);
}

}  // namespace

TimeIntegrator::TimeIntegrator(const model::Assembler& assembler, const DynamicOptions& options,
                               const SolveLog& log)
    : model_(assembler.model()),
      assembler_(assembler),
      o_(options),
      log_(log),
      gamma_(options.gamma),
      beta_(options.beta),
      alpha_(options.hht_alpha),
      motion_loads_(assembler.model().hasMotionLoads() &&
                    options.load_matrices != DynamicOptions::LoadMatrixUpdate::Off),
      contact_loads_(motion_loads_ && assembler.model().hasContactLoads()),
      linear_(motion_loads_ || options.pressure_load_stiffness || assembler.hasDamping()
                  ? MatrixKind::Unsymmetric
                  : MatrixKind::Symmetric) {
  if (alpha_ != 0.0) {
    gamma_ = 0.5 - alpha_;
    beta_ = 0.25 * (1.0 - alpha_) * (1.0 - alpha_);
  }
  masses_ = assembler_.elementMasses(o_.mass);
  assembler_.mass(model_.initialState(), o_.mass, M_);
}

// Damping force C v on the free dofs, C = rayleigh_mass M + rayleigh_stiffness K0.
VectorXd TimeIntegrator::damping(const VectorXd& v_free) const {
  VectorXd f = VectorXd::Zero(v_free.size());
  if (o_.rayleigh_mass != 0.0) f += o_.rayleigh_mass * (M_ * v_free);
  if (o_.rayleigh_stiffness != 0.0) f += o_.rayleigh_stiffness * (K0_ * v_free);
  return f;
}

void TimeIntegrator::balance(const model::State& x, bool tangent, bool loads, Residual& R) {
  outOfBalance(assembler_, x, tangent ? &K_ : nullptr, loads ? &loads_ : nullptr, scratch_.balance,
               R);
  if (tangent && o_.pressure_load_stiffness) assembler_.subtractLoadStiffness(x, K_);
  if (assembler_.hasDamping()) {
    assembler_.dampingForce(x, scratch_.viscous, tangent ? &viscous_ : nullptr);
    assembler_.restrictToFree(scratch_.viscous, scratch_.free);
    R.free -= scratch_.free;
  }
  if (o_.rayleigh_mass != 0.0 || o_.rayleigh_stiffness != 0.0)
    R.free -= damping(assembler_.restrictToFree(asVector(x.velocity)));
  if (loads) ++report_.load_matrix_updates;
}

void TimeIntegrator::summedWeights(double h) {
  const double a0 = 1.0 / (beta_ * h * h);
  const double c = (1.0 + alpha_) * gamma_ / (beta_ * h);
  viscous_.summed = model::LoadMatrices::Weights{1.0 + alpha_, c, 0.0};
  loads_.summed = model::LoadMatrices::Weights{1.0 + alpha_, c, (1.0 + alpha_) * a0};
}

// Effective tangent (Eq. 4.63): (1 + alpha) (K_T + K_d + K_L) + gamma / (beta h) (1 + alpha)
// (C + C_d + C_L) + a0 (M + (1 + alpha) M_L), with C = a_M M + a_K K0, the internal damping's
// dF_d/du = K_d and dF_d/du' = C_d, and the motion loads' stiffness K_L, damping C_L and added
// mass M_L. The internal damping's and the motion loads' matrices arrive summed with these
// weights (summedWeights), one matrix each; everything is on the assembler's one pattern, so
// the sum is taken coefficient by coefficient, without a sparse merge or an allocation.
void TimeIntegrator::factorEffectiveTangent(double h) {
  const double a0 = 1.0 / (beta_ * h * h);
  const double c = (1.0 + alpha_) * gamma_ / (beta_ * h);
  if (Keff_.nonZeros() != K_.nonZeros()) Keff_ = K_;  // the pattern, once
  Keff_.coeffs() = (1.0 + alpha_) * K_.coeffs() + (a0 + c * o_.rayleigh_mass) * M_.coeffs();
  if (o_.rayleigh_stiffness != 0.0) Keff_.coeffs() += (c * o_.rayleigh_stiffness) * K0_.coeffs();
  if (assembler_.hasDamping()) Keff_.coeffs() += viscous_.stiffness.coeffs();
  if (motion_loads_) Keff_.coeffs() += loads_.stiffness.coeffs();
  if (!linear_.factorize(Keff_)) {
    singular_ = true;
    return;
  }
  factor_h_ = h;
  ++report_.tangent_updates;
}

// The supports at the end of a (sub-)step: their model histories, or the motion drive() set.
void TimeIntegrator::applySupports(model::State& next, const model::State& previous,
                                   double h) const {
  assembler_.applyPrescribed(next);
  for (const auto& [dof, t] : targets_) {
    const auto [n, k] = dof;
    const double f = std::clamp((next.time - t.start_time) / t.duration, 0.0, 1.0);
    next.displacement(k, n) = t.start_u + f * (t.end_u - t.start_u);
    next.velocity(k, n) = t.start_v + f * (t.end_v - t.start_v);
    next.acceleration(k, n) = (next.velocity(k, n) - previous.velocity(k, n)) / h;
  }
}

// One Newton solve of the step from s to s + h. Each iteration evaluates the forces once, with
// the matrices it needs from the same sweep; the evaluation that accepts the step leaves its
// balance and matrices for the next step's start (kept_), which would otherwise evaluate them
// again at that very state.
bool TimeIntegrator::attempt(model::State& s, double h, IterationRecord& rec) {
  const double a0 = 1.0 / (beta_ * h * h), a1 = 1.0 / (beta_ * h), a2 = 0.5 / beta_ - 1.0;
  VectorXd &u_n = scratch_.u_n, &v_n = scratch_.v_n, &acc_n = scratch_.acc_n;
  assembler_.restrictToFree(asVector(s.displacement), u_n);
  assembler_.restrictToFree(asVector(s.velocity), v_n);
  assembler_.restrictToFree(asVector(s.acceleration), acc_n);
  if (o_.rayleigh_stiffness != 0.0) {
    VectorXd F;
    assembler_.internalForce(s, F, &K0_);
  }
  const bool self_corrective = o_.flavour == NewtonFlavour::SelfCorrective;
  // The matrices that follow the iterations: the tangent in full Newton (and in the
  // self-corrective scheme, whose one solve uses the step's start, so the accepting evaluation's
  // serves the next step), the motion loads' with load_matrices: iteration. The self-corrective
  // scheme's one evaluation after its solve is the one that accepts the step, known in advance,
  // so it takes the motion loads' matrices as well: the next step's start needs exactly these,
  // which would otherwise cost a sweep of their own.
  const bool tangent_iterates = o_.flavour == NewtonFlavour::Full || self_corrective;
  const bool loads_iterate =
      motion_loads_ &&
      (self_corrective || o_.load_matrices == DynamicOptions::LoadMatrixUpdate::Iteration);
  // The first solve's matrices: the tangent at the step's start when it is refreshed this step;
  // the motion loads' always renewed (both update schedules), at the step's start, or at the
  // predictor, where the iterations start, when the model has contact loads. A point of a line
  // that the predictor puts on the seabed then meets the bed's stiffness in the first solve: with
  // the matrices of the start, where it was still above the bed, that solve drove it metres into
  // the bed, and Newton needed backtracking and a dozen iterations to come back (OC4 at dt 0.4 s:
  // 6,351 Newton iterations and 2,155 backtracks with the start's, 4,798 and 487 with the
  // predictor's). Without contact the start's serve better: the predictor's acceleration,
  // -u''_n, is no guide to the loads' added-mass terms (a slack rope snapping in waves then
  // stalls). The structure's tangent stays the start's, which the predictor's does not better;
  // the self-corrective scheme's one solve takes all its matrices at the start (Eq. 4.20).
  const bool refresh_each_step = tangent_iterates ||
                                 steps_since_update_ + 1 >= std::max(1, o_.stiffness_update) ||
                                 h != factor_h_;
  const bool loads_at_predictor = contact_loads_ && !self_corrective;
  // What the last step kept was summed with its own step's weights.
  const bool kept = kept_.valid && kept_.h == h && model::sameState(kept_.state, s);
  summedWeights(h);
  const bool tangent_missing = refresh_each_step && !(kept && kept_.tangent);
  const bool loads_missing = motion_loads_ && !loads_at_predictor && !(kept && kept_.loads);
  VectorXd& previous_balance = scratch_.previous_balance;  // HHT: P_n - F_n - F_d,n - C v_n
  if (tangent_missing || loads_missing || (alpha_ != 0.0 && !kept)) {
    Residual& start = scratch_.residual;
    balance(s, tangent_missing, loads_missing, start);
    if (tangent_missing) floor_ = start.floor * start.scale / std::max(start.scale, force_scale_);
    previous_balance = start.free;
  } else {
    previous_balance = kept_.balance;
  }
  kept_.valid = false;

  model::State& next = scratch_.next;
  next = s;
  next.time = s.time + h;
  if (std::abs(next.time - end_time_) <= 1e-9 * h) next.time = end_time_;  // not a rounded sum
  applySupports(next, s, h);
  // Predictor: the motion continued at its last velocity, u_n + h u'_n, which starts Newton
  // closer than u_n does (OC4's surge: a quarter fewer iterations). Not with the acceleration
  // too: u''_n carries the stiff axial modes, which h^2 / 2 u''_n amplifies (a light line in a
  // wave needs twice the iterations). The self-corrective scheme keeps the dissertation's u_n
  // (its one solve from there is the step, Eq. 4.20).
  VectorXd& u = scratch_.u;
  u = u_n;
  if (!self_corrective) u += h * v_n;
  trace_.start();
  singular_ = false;
  step_ = StepSolve{h,
                    a0,
                    a1,
                    a2,
                    self_corrective,
                    tangent_iterates,
                    loads_iterate,
                    loads_at_predictor,
                    refresh_each_step};
  NewtonSettings settings;
  settings.max_iterations = o_.max_iterations;
  // Eq. 4.20: the self-corrective scheme's one solve is accepted, its residual carried into the
  // next step, while that residual stays acceptable (a step it throws further out of balance
  // is cut like any other that fails).
  settings.single_solve = self_corrective;
  const NewtonOutcome out = newtonSolve(*this, settings, model_, trace_, rec, scratch_.newton);
  report_.iterations += out.solves;
  report_.backtracks += out.backtracks;
  if (!out.converged()) return false;
  force_scale_ = step_.scale;
  s = next;
  steps_since_update_ = refresh_each_step ? 0 : steps_since_update_ + 1;
  s.motion = record(s);
  kept_.valid = true;
  kept_.tangent = step_.tangent;
  kept_.loads = step_.loads;
  kept_.h = h;
  kept_.state = s;
  kept_.balance = scratch_.balance_here;
  return true;
}

// The iterate u's acceleration and velocity by Newmark (Eq. 4.57-4.58), and its residual (Eq.
// 4.63) with the matrices the step's schedule takes at this iteration.
void TimeIntegrator::evaluate(int it, VectorXd& R_out, IterateNorms& norms) {
  const StepSolve& k = step_;
  model::State& next = scratch_.next;
  const VectorXd &u_n = scratch_.u_n, &v_n = scratch_.v_n, &acc_n = scratch_.acc_n;
  VectorXd &u = scratch_.u, &acc = scratch_.acceleration, &v = scratch_.velocity;
  acc = k.a0 * (u - u_n) - k.a1 * v_n - k.a2 * acc_n;       // Eq. 4.57
  v = v_n + k.h * ((1.0 - gamma_) * acc_n + gamma_ * acc);  // Eq. 4.58
  setFree(model_, u, next.displacement);
  setFree(model_, v, next.velocity);
  setFree(model_, acc, next.acceleration);
  step_.tangent = it > 0 && k.tangent_iterates;
  step_.loads = it > 0 ? k.loads_iterate : k.loads_at_predictor;
  Residual& R = scratch_.residual;
  balance(next, step_.tangent, step_.loads, R);
  scratch_.balance_here = R.free;
  VectorXd& inertia_full = scratch_.inertia;
  assembler_.inertiaForce(masses_, next, inertia_full);
  assembler_.restrictToFree(inertia_full, scratch_.free);
  R.free = (1.0 + alpha_) * R.free - scratch_.free;  // Eq. 4.63
  if (alpha_ != 0.0) R.free -= alpha_ * scratch_.previous_balance;
  // The forces pass through zero twice a period, so the residual is measured against the
  // largest force seen in the run, not the instantaneous one (round-off would stall Newton).
  const double scale = std::max({R.scale, inertia_full.norm(), force_scale_});
  if (step_.tangent) floor_ = R.floor * R.scale / scale;
  R.scale = step_.scale = scale;
  norms.residual = R.relative();
  norms.residual_floor = floor_;
  R_out.swap(R.free);
}

bool TimeIntegrator::accepts(const IterateNorms& norms) const {
  return step_.self_corrective ? acceptable(norms.residual, norms.residual_floor)
                               : converged(o_.convergence, norms);
}

bool TimeIntegrator::increment(int it, const VectorXd& R, VectorXd& du) {
  const bool new_matrices =
      it == 0 ? step_.refresh_each_step || motion_loads_ : step_.tangent || step_.loads;
  if (new_matrices) {
    factorEffectiveTangent(step_.h);
    if (singular_) return false;
  }
  linear_.solve(R, du);
  return true;
}

void TimeIntegrator::add(const VectorXd& du, double scale) { scratch_.u += scale * du; }

// The increment against the element size, its floor from the iterate it was solved at.
void TimeIntegrator::measure(const VectorXd& du, IterateNorms& norms) const {
  incrementNorm(assembler_, du, scratch_.next.displacement, norms);
}

void TimeIntegrator::fail(const model::State& s, double h, const IterationRecord& rec) const {
  std::ostringstream m;
  m << "time step at t = " << s.time << " s did not converge even with dt = " << h << " s ("
    << rec.iteration << " iterations, displacement norm " << rec.displacement_norm << ", residual "
    << rec.residual_norm << "): ";
  if (singular_)
    m << "the effective tangent K + M / (beta dt^2) is singular: a free dof has neither mass "
         "nor stiffness";
  else
    m << trace_.diagnosis(log_);
  if (trace_.lost())
    m << " (a displacement running away there is a motion nothing resists: a mechanism, a "
         "slack line, or a load the structure cannot carry)";
  throw ConvergenceError(m.str(), rec);
}

void TimeIntegrator::advance(model::State& s, double h, int depth,
                             const std::function<void(const model::State&)>& on_step) {
  IterationRecord rec{report_.steps + 1, 0, s.load_factor, 0.0, 0.0};
  if (attempt(s, h, rec)) {
    ++report_.steps;
    log_.report(rec);
    if (on_step) on_step(s);
    return;
  }
  if (depth >= o_.max_step_cuts) fail(s, h, rec);
  ++report_.cuts;
  std::ostringstream m;
  m << "t = " << s.time << " s: Newton failed with dt = " << h << " s, halving";
  log_.say(m.str());
  advance(s, 0.5 * h, depth + 1, on_step);
  advance(s, 0.5 * h, depth + 1, on_step);
}

// Zienkiewicz and Xie's estimate of the step's displacement error, e = h^2 (beta - 1/6)
// (u''_n+1 - u''_n), against the displacement the step made, |e| / |u_n+1 - u_n| over the free
// dofs: for a motion of frequency omega, (omega h)^2 / 12 (average acceleration), the step's
// relative phase error. (Against the forces, K e, the stiff axial vibrations that Newmark filters
// out, and that a line's tensions hardly feel, would set the step.)
double TimeIntegrator::localError(double h) const {
  const double e =
      (h * h * std::abs(beta_ - 1.0 / 6.0)) * (scratch_.acceleration - scratch_.acc_n).norm();
  const double du = (scratch_.u - scratch_.u_n).norm();
  const double floor = 1e-12 * assembler_.elementSize();  // a structure at rest
  return e / std::max(du, floor) / o_.adaptive->tolerance;
}

void TimeIntegrator::adaptiveSteps(model::State& s, double t_end,
                                   const std::function<void(const model::State&)>& on_step) {
  const AdaptiveSteps& a = *o_.adaptive;
  const double dt_min = a.dt_min > 0.0 ? a.dt_min : 1e-9 * a.duration;
  const double dt_max = a.dt_max > 0.0 ? a.dt_max : a.duration;
  if (!(h_ > 0.0)) h_ = std::min(dt_max, a.dt_start > 0.0 ? a.dt_start : 1e-4 * a.duration);
  bool retried = false;
  while (s.time < t_end) {
    const double remaining = t_end - s.time;
    double h = std::min(h_, dt_max);
    const bool landing = h >= remaining * (1.0 - 1e-12);
    if (landing)
      h = remaining;  // the last step lands on t_end
    else if (h > 0.5 * remaining)
      h = 0.5 * remaining;  // two steps of half the rest rather than one and a sliver
    const model::State start = s;
    const int steps_since_update = steps_since_update_;
    const double force_scale = force_scale_;
    const int iterations = report_.iterations;
    IterationRecord rec{report_.steps + 1, 0, s.load_factor, 0.0, 0.0};
    if (!attempt(s, h, rec)) {
      if (h <= dt_min) fail(s, h, rec);
      ++report_.cuts;
      std::ostringstream m;
      m << "t = " << s.time << " s: Newton failed with dt = " << h << " s, halving";
      log_.say(m.str());
      h_ = std::max(0.5 * h, dt_min);
      retried = true;
      continue;
    }
    const double error = localError(h);
    // The step the error asks for, as if the step meant had been taken: one shortened to land
    // has (h / meant)^3 of its error.
    const double meant = std::max(h, std::min(h_, dt_max));
    const double next = StepControl::next(meant, error * std::pow(meant / h, 3),
                                          report_.iterations - iterations, retried);
    if (!StepControl::accepts(error) && h > dt_min) {
      s = start;
      steps_since_update_ = steps_since_update;
      force_scale_ = force_scale;
      kept_.valid = false;
      ++report_.rejections;
      h_ = std::clamp(std::min(next, 0.9 * h), dt_min, dt_max);
      retried = true;
      continue;
    }
    ++report_.steps;
    log_.report(rec);
    if (on_step) on_step(s);
    h_ = std::clamp(next, dt_min, dt_max);
    retried = false;
  }
}

void TimeIntegrator::step(model::State& s, double dt,
                          const std::function<void(const model::State&)>& on_step) {
  stepTo(s, s.time + dt, on_step);
}

void TimeIntegrator::setTargets(const model::State& s, double t_end) {
  end_time_ = t_end;
  for (auto& [dof, t] : targets_) {
    t.start_u = s.displacement(dof.second, dof.first);
    t.start_v = s.velocity(dof.second, dof.first);
    t.start_time = s.time;
    t.duration = t_end - s.time;
  }
}

void TimeIntegrator::stepTo(model::State& s, double t_end,
                            const std::function<void(const model::State&)>& on_step) {
  setTargets(s, t_end);
  try {
    advance(s, t_end - s.time, 0, on_step);
  } catch (...) {
    targets_.clear();
    throw;
  }
  targets_.clear();
}

void TimeIntegrator::advanceTo(model::State& s, double t_end,
                               const std::function<void(const model::State&)>& on_step) {
  if (!o_.adaptive) {
    stepTo(s, t_end, on_step);
    return;
  }
  setTargets(s, t_end);
  try {
    adaptiveSteps(s, t_end, on_step);
  } catch (...) {
    targets_.clear();
    throw;
  }
  targets_.clear();
}

void TimeIntegrator::drive(int node, int component, double displacement, double velocity) {
  if (node < 0 || node >= model_.nodeCount() || component < 0 || component > 2 ||
      !model_.isConstrained(node, component))
    throw std::invalid_argument("drive: node " + std::to_string(node) + " component " +
                                std::to_string(component) + " is not a constrained dof");
  targets_[{node, component}] = Target{0.0, 0.0, displacement, velocity, 0.0, 0.0};
}

// u'' at the start from equilibrium: (M + M_L) a = P - F - F_d - C v - M_p a_p on the free dofs,
// with P taken at zero free acceleration, F_d the internal damping, M_L the motion loads' added
// mass and M_p a_p the inertia of the prescribed supports' accelerations; zero if the mass is
// singular.
void TimeIntegrator::initialAcceleration(model::State& s) {
  assembler_.applyPrescribed(s);
  setFree(model_, VectorXd::Zero(model_.equationCount()), s.acceleration);
  VectorXd inertia_full;
  assembler_.inertiaForce(masses_, s, inertia_full);  // prescribed accelerations only
  loads_.summed.reset();  // the added mass alone; the first step sums them again
  Residual start;
  balance(s, false, model_.hasMotionLoads(), start);
  const VectorXd rhs = start.free - assembler_.restrictToFree(inertia_full);
  model::SparseMatrix mass = M_;
  if (model_.hasMotionLoads()) mass.coeffs() += loads_.mass.coeffs();
  LinearSolver mass_solver(model_.hasMotionLoads() ? MatrixKind::Unsymmetric
                                                   : MatrixKind::Symmetric);
  if (mass_solver.factorize(mass)) setFree(model_, mass_solver.solve(rhs), s.acceleration);
}

void TimeIntegrator::start(model::State& s) {
  kept_.valid = false;
  s.still = false;  // the waves act again
  if (o_.load_factor) s.load_factor = *o_.load_factor;
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
  s.motion = record(s);
}

model::MotionRecord TimeIntegrator::record(const model::State& s) const {
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

IntegratorCheckpoint TimeIntegrator::save(const model::State& s) {
  factor_h_ = -1.0;
  kept_.valid = false;
  return {s, steps_since_update_, force_scale_, h_};
}

void TimeIntegrator::restore(const IntegratorCheckpoint& checkpoint, model::State& s) {
  s = checkpoint.state;
  steps_since_update_ = checkpoint.steps_since_update;
  force_scale_ = checkpoint.force_scale;
  h_ = checkpoint.next_step;
  factor_h_ = -1.0;  // the factorisation belongs to a later state: the next step makes its own
  kept_.valid = false;
  targets_.clear();
}

}  // namespace flexmoor::solve
