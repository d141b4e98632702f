#pragma once
// Viscous relaxation (Appendix C): finds the static equilibrium of a structure whose start is
// unstable (a slack, unstressed cable) by integrating D u' + F(u) = P (Eq. C.6) with implicit
// steps until the motion dies out (Eq. C.15) and the residual vanishes.
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct RelaxationReport {
  int steps = 0;               // pseudo-time steps taken (the dissertation's "increments")
  int iterations = 0;          // Newton iterations over all steps
  double final_damping = 0.0;  // C at the end
  double change_ratio = 0.0;   // Eq. C.15 at the last step
  double residual_norm = 0.0;
};

RelaxationReport relax(const model::Assembler& assembler, model::State& state,
                       const RelaxationOptions& options, const SolveLog& log = {});

}  // namespace flexmoor::solve
