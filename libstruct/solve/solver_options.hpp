#pragma once
// Options of the static solvers, as a case file states them.
namespace flexmoor::solve {

enum class NewtonFlavour {
  Full,      // Newton-Raphson: tangent updated every iteration
  Modified,  // modified Newton: tangent updated every `stiffness_update` iterations and at the
             // start of every increment
  Bfgs,      // quasi-Newton: the tangent of the increment's start (refreshed like Modified),
             // improved by BFGS rank-two updates between refreshes
  SelfCorrective,  // Eq. 4.20: one solve per increment (or time step) with the tangent and the
                   // full residual of its start, accepted without iterating; what is left out of
                   // balance is carried into the next increment and corrected there, so the error
                   // stays that of one Newton step, O(increment^2). An increment or time step is
                   // accepted only while that residual stays below kAcceptedResidual; a static
                   // solve's last increment is corrected until it converges.
};

// When the Newton iterations of a solve have converged, the one test of every solver: statics in
// each flavour, arc length, viscous relaxation's pseudo-time steps and time steps
// (equilibrium.hpp, converged()). Eq. 5.1, each norm measured against a scale that means
// something for the model at hand:
//  - residual: |R| over the free dofs against the largest force in play S (internal, external
//    and, in a time step, inertial: Residual::scale), never asking for less than round-off leaves
//    of it (Residual::floor);
//  - displacement: the Newton increment's largest component, max |du_i|, against the model's
//    mean element size L (Assembler::elementSize), never asking for less than round-off leaves
//    of the coordinates. (Against the total displacement, as Eq. 5.1 reads, a line hanging 600 m
//    from its straight reference passes after one iteration: strict-looking and loose.)
// use_residual alone ends the iterations on the first, use_displacement alone on the second,
// both (the default) on both. Whichever ends them, a state whose residual is above
// kAcceptedResidual of S is never taken for an equilibrium (equilibrium.hpp).
struct Convergence {
  bool use_displacement = true;
  bool use_residual = true;
  double displacement_tolerance = 1e-6;  // max |du_i| / L
  double residual_tolerance = 1e-8;      // |R| / S
};

// Arc-length continuation (Crisfield): the load factor becomes an unknown and each increment is
// constrained to |du|^2 + psi^2 dlambda^2 |P|^2 = ds^2, so a run passes limit points and flat
// stretches of the equilibrium path. psi = 0 is the cylindrical form, psi = 1 the spherical one.
struct ArcLengthOptions {
  double psi = 0.0;
  int desired_iterations = 5;  // ds grows or shrinks by sqrt(desired / used) per increment
  double max_growth = 2.0;     // bound on that factor
  int max_increments = 2000;
  int max_cuts = 10;  // a failed increment is retried with ds / 2
};

enum class LoadControl { Load, ArcLength };

struct StaticOptions {
  double load_factor = 1.0;  // target load factor, reached from the current one
  int increments = 1;        // load control: equal increments; arc length: the first increment
                             // is 1 / increments of the way
  LoadControl control = LoadControl::Load;
  ArcLengthOptions arc;
  NewtonFlavour flavour = NewtonFlavour::Full;
  int stiffness_update = 1;  // modified Newton: iterations between tangent updates
  int max_iterations = 50;
  Convergence convergence;
  // Follower pressure: with the consistent load stiffness dP/du (non-symmetric, UMFPACK), or, as
  // the dissertation does (Eq. 4.41), without it, iterating on the symmetric tangent alone.
  bool pressure_load_stiffness = false;
  // The loads see still water (gravity, buoyancy, current; no waves), unless the waves are
  // frozen as they stand at the state's time.
  bool frozen_waves = false;
};

// Viscous relaxation (Appendix C): D u' + F(u) = P with D = C I, implicit steps of unit
// pseudo-time, C reduced after each step.
struct RelaxationOptions {
  double load_factor = 1.0;
  double tolerance = 1e-3;               // Eq. C.15 on the step's displacement change
  double damping = 1.0e4;                // C, the damping matrix constant (Eq. C.11)
  double initial_damping_factor = 0.01;  // mu(0) of Eq. C.13: C(k+1) = mu(k) r(k) C(k)
  double decrement = 1.0;                // gamma of Eq. C.14: mu(k+1) = gamma mu(k)
  double residual_tolerance = 1e-8;      // equilibrium check: |R| < tol * max(|P|, |F|)
  int max_steps = 500;
  int max_iterations = 30;    // Newton iterations inside one pseudo-time step
  bool frozen_waves = false;  // as StaticOptions
};

}  // namespace flexmoor::solve

#include <optional>
#include <vector>

#include "libstruct/element/element.hpp"

namespace flexmoor::solve {

// A run of equal time steps; a schedule is a list of them (the dissertation's Example 9 uses
// 50 steps of 0.02 s, then 0.05 s).
struct TimeSegment {
  double dt = 0.0;
  int steps = 0;
};

// Time steps chosen as the integration goes (the schedule empty): each step's size follows the
// local error of the last one (step_control.hpp), Zienkiewicz and Xie's displacement error against
// the displacement the step made, (omega h)^2 / 12 for a motion of frequency omega; a step above
// `tolerance` is taken again, shorter. The default, 0.01, is about 18 steps a period of the
// motion that dominates (a snap's peak tension sampled within 1.5%).
struct AdaptiveSteps {
  double duration = 0.0;    // the time the step covers
  double tolerance = 0.01;  // of the local error
  double dt_min = 0.0;      // 0: duration * 1e-9
  double dt_max = 0.0;      // 0: no bound but the duration
  double dt_start = 0.0;    // the first step tried; 0: duration * 1e-4
};

// Newmark time integration (Eq. 4.55-4.63) with Newton iterations in every step.
struct DynamicOptions {
  std::vector<TimeSegment> schedule;
  std::optional<AdaptiveSteps> adaptive;  // instead of a schedule
  // The load factor held through the step (it scales the loads and prescribed displacements that
  // have no history); unset: the state's, the factor the previous step left.
  std::optional<double> load_factor;
  double gamma = 0.5;  // the dissertation's constants (average acceleration)
  double beta = 0.25;
  // HHT-alpha in [-1/3, 0]: numerical damping of the highest modes; when non-zero, gamma and beta
  // are set to (1 - 2 alpha) / 2 and (1 - alpha)^2 / 4 (second order, unconditionally stable).
  double hht_alpha = 0.0;
  NewtonFlavour flavour = NewtonFlavour::Full;
  int stiffness_update = 1;  // modified Newton: time steps between tangent updates
  int max_iterations = 30;
  Convergence convergence;
  element::MassKind mass = element::MassKind::Consistent;
  double rayleigh_mass = 0.0;  // C = rayleigh_mass M + rayleigh_stiffness K_T(start of step)
  double rayleigh_stiffness = 0.0;
  int max_step_cuts = 6;  // a failed step is halved, at most this many times
  // The motion-dependent loads' stiffness, damping and added mass in the effective tangent
  // (non-symmetric: LU): evaluated at every iteration (the default: Newton stays quadratic when a
  // point touches down on the seabed within the step), at the first iteration of every step
  // only, or never (their forces stay in the residual; only to measure what the matrices are
  // worth).
  enum class LoadMatrixUpdate { Step, Iteration, Off };
  LoadMatrixUpdate load_matrices = LoadMatrixUpdate::Iteration;
  // Follower pressure: its load stiffness dP/du in the tangent (non-symmetric, LU), as in statics.
  bool pressure_load_stiffness = false;
};

}  // namespace flexmoor::solve
