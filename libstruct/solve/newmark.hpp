#pragma once
// Nonlinear time integration: Newmark's method (Eq. 4.55-4.63) with Newton-Raphson or modified
// Newton iterations on the full residual in every step (the self-corrective scheme), optional
// HHT-alpha numerical damping, Rayleigh damping, and automatic step cutting when Newton fails.
#include <functional>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/solver_options.hpp"
#include "libstruct/solve/time_integrator.hpp"

namespace flexmoor::solve {

// Integrates from state.time over the schedule (a loop of TimeIntegrator::step), or over
// options.adaptive's duration in steps of its choosing, at options.load_factor when it is set (else at the
// state's). The start acceleration is the one the state carries when an earlier integration
// accepted it under the same load factor and equation of motion (state.motion), and is solved for
// from equilibrium otherwise. `on_step` sees every accepted state. On failure throws
// ConvergenceError, naming the likely cause, with the state at the last accepted step.
DynamicReport integrate(const model::Assembler& assembler, model::State& state,
                        const DynamicOptions& options, const SolveLog& log = {},
                        const std::function<void(const model::State&)>& on_step = {});

}  // namespace flexmoor::solve
