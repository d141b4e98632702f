#pragma once
// Incremental/iterative static solution (Chapter IV): the load factor goes from the state's value
// to the target in equal increments; each increment is solved by Newton-Raphson or modified
// Newton on K_T du = P - F, with convergence by Eq. 5.1 and/or the residual.
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct IncrementSummary {
  int increment;
  double load_factor;
  int iterations;
  int tangent_updates;
  double displacement_norm;
  double residual_norm;
};

struct StaticReport {
  std::vector<IncrementSummary> increments;
};

// Solves in place. On failure throws ConvergenceError and leaves `state` at the last converged
// increment.
StaticReport solveStatic(const model::Assembler& assembler, model::State& state,
                         const StaticOptions& options, const SolveLog& log = {});

}  // namespace flexmoor::solve
