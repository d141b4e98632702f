#pragma once
// Arc-length continuation (Crisfield's cylindrical / spherical method) for load-controlled static
// paths with limit points and flat stretches; automatic step size by iteration count.
#include "libstruct/solve/static_solver.hpp"

namespace flexmoor::solve {

// Follows the path from state.load_factor to options.load_factor. The loads must be
// proportional (P = lambda P(u)); prescribed non-zero displacements are refused. The last
// increment lands on the target load factor exactly (a load-controlled correction).
StaticReport solveArcLength(const model::Assembler& assembler, model::State& state,
                            const StaticOptions& options, const SolveLog& log = {});

}  // namespace flexmoor::solve
