#include "libstruct/solve/newton.hpp"

#include <cmath>

namespace flexmoor::solve {

NewtonOutcome newtonSolve(NewtonProblem& problem, const NewtonSettings& settings,
                          const model::Model& model, NewtonTrace& trace, IterationRecord& rec,
                          NewtonWork& work) {
  NewtonOutcome out;
  IterateNorms norms;
  Backtracking backtracking;
  Eigen::VectorXd &R = work.residual, &du = work.increment;
  for (int it = 0; it <= settings.max_iterations; ++it) {
    problem.evaluate(it, R, norms);
    rec.residual_norm = norms.residual;
    trace.residual(norms.residual);
    if (it > 0) {
      problem.evaluated(rec);
      if (problem.accepts(norms)) {
        out.result = NewtonResult::Converged;
        return out;
      }
      if (settings.single_solve) return out;
    }
    if (it == settings.max_iterations) return out;
    if (settings.backtracking && backtracking.halve(it, norms.residual)) {
      du *= 0.5;  // half of the increment taken back
      problem.add(du, -1.0);
      ++out.backtracks;
      problem.measure(du, norms);
      rec.displacement_norm = norms.displacement;
      continue;
    }
    if (!std::isfinite(norms.residual)) {
      out.result = NewtonResult::NonFinite;
      return out;
    }
    if (!problem.increment(it, R, du)) {
      out.result = NewtonResult::NoIncrement;
      return out;
    }
    problem.add(du, 1.0);
    trace.increment(model, du);
    ++out.solves;
    rec.iteration = it + 1;
    problem.measure(du, norms);
    rec.displacement_norm = norms.displacement;
  }
  return out;
}

NewtonOutcome newtonSolve(NewtonProblem& problem, const NewtonSettings& settings,
                          const model::Model& model, NewtonTrace& trace, IterationRecord& rec) {
  NewtonWork work;
  return newtonSolve(problem, settings, model, trace, rec, work);
}

}  // namespace flexmoor::solve
