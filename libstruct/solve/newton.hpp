#pragma once
// The one Newton loop of every implicit solver: a static increment in each flavour, an
// arc-length increment, a pseudo-time step of viscous relaxation and a time step. After MFEM's
// NewtonSolver over an Operator: the analysis supplies its residual, its increment and how an
// iterate moves (NewtonProblem); the loop owns the order of things, the backtracking line
// search, the trace a failure's diagnosis reads, and the rule that no iterate is accepted whose
// residual has not been measured at that very iterate.
#include <Eigen/Core>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/solve_log.hpp"

namespace flexmoor::solve {

// What an analysis supplies. Its unknowns are its own (a static solve's displacements, a time
// step's end state, an arc-length increment's displacements and load factor); the loop sees only
// the residual and the increments on the free dofs.
class NewtonProblem {
 public:
  virtual ~NewtonProblem() = default;
  // The residual at the current iterate, `it` (0: the start), into R, with its norm relative to
  // the forces in play and its round-off floor into norms.residual and norms.residual_floor.
  virtual void evaluate(int it, Eigen::VectorXd& R, IterateNorms& norms) = 0;
  // Whether the iterate `it` > 0, measured by `norms`, is the solution: converged() with the
  // analysis's Convergence, or, for a single solve (NewtonSettings::single_solve), acceptable().
  virtual bool accepts(const IterateNorms& norms) const = 0;
  // The increment from the residual R of iterate `it` into du, which holds the last increment
  // taken on entry (BFGS updates from it); the tangent is factorised as the analysis's schedule
  // asks. False when none can be formed (a singular tangent, an arc-length constraint without a
  // root).
  virtual bool increment(int it, const Eigen::VectorXd& R, Eigen::VectorXd& du) = 0;
  // Moves the iterate by scale du (scale 1: the increment taken; -1/2: half of it taken back).
  virtual void add(const Eigen::VectorXd& du, double scale) = 0;
  // The increment's norm and its round-off floor into norms.displacement and
  // norms.displacement_floor (incrementNorm: max |du_i| over the element size).
  virtual void measure(const Eigen::VectorXd& du, IterateNorms& norms) const = 0;
  // Each evaluated iterate after the start, for the log.
  virtual void evaluated(const IterationRecord&) const {}
};

struct NewtonSettings {
  int max_iterations = 50;  // increments solved for at most
  // Backtracking (equilibrium.hpp): an increment after the first that raised the residual is
  // halved. Not for arc length, whose increments keep to its constraint.
  bool backtracking = true;
  // The self-corrective scheme (Eq. 4.20): one solve, its iterate accepted or not, no more.
  bool single_solve = false;
};

enum class NewtonResult {
  Converged,     // the last iterate is the solution, its residual measured there
  NotConverged,  // the iterations (or the single solve) ended without it
  NonFinite,     // the residual became NaN or infinite
  NoIncrement,   // NewtonProblem::increment could not form one
};

struct NewtonOutcome {
  NewtonResult result = NewtonResult::NotConverged;
  int solves = 0;      // increments solved for
  int backtracks = 0;  // increments halved
  bool converged() const { return result == NewtonResult::Converged; }
};

// The loop's vectors, which a caller that solves many times keeps so that its iterations allocate
// nothing.
struct NewtonWork {
  Eigen::VectorXd residual, increment;
};

// Iterates `problem` from its current iterate. `rec` carries the iteration count and the last
// norms (for the log and a failure's message); `trace` gets every residual and increment (it is
// not restarted: an analysis may record its predictor first). `model` names the dofs of the trace.
NewtonOutcome newtonSolve(NewtonProblem& problem, const NewtonSettings& settings,
                          const model::Model& model, NewtonTrace& trace, IterationRecord& rec,
                          NewtonWork& work);
// The same with vectors of its own.
NewtonOutcome newtonSolve(NewtonProblem& problem, const NewtonSettings& settings,
                          const model::Model& model, NewtonTrace& trace, IterationRecord& rec);

}  // namespace flexmoor::solve
