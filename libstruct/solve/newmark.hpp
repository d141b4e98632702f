#pragma once
// Nonlinear time integration: Newmark's method (Eq. 4.55-4.63) with Newton-Raphson or modified
// Newton iterations on the full residual in every step (the self-corrective scheme), optional
// HHT-alpha numerical damping, Rayleigh damping, and automatic step cutting when Newton fails.
#include <functional>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct DynamicReport {
  int steps = 0;       // accepted steps, cut sub-steps included
  int iterations = 0;  // Newton iterations over all steps
  int cuts = 0;        // how often a step was halved
  int tangent_updates = 0;
};

// Integrates from state.time over the schedule. `on_step` sees every accepted state. On failure
// throws ConvergenceError with the state at the last accepted step.
DynamicReport integrate(const model::Assembler& assembler, model::State& state,
                        const DynamicOptions& options, const SolveLog& log = {},
                        const std::function<void(const model::State&)>& on_step = {});

}  // namespace flexmoor::solve
