#pragma once
// What a failing solver can tell about why it fails, for its ConvergenceError message: the course
// of the residual over the Newton iterations of one increment or time step (diverging, stalling,
// turning non-finite) and the dof that moves most (where a displacement runs away).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "libstruct/model/model.hpp"
#include "libstruct/solve/solve_log.hpp"

namespace flexmoor::solve {

// The free dof with the largest |du| of a free-dof vector.
struct LargestMove {
  int node = -1;
  int component = -1;  // 0, 1, 2 = x, y, z
  double value = 0.0;  // du there, signed
};
LargestMove largestMove(const model::Model& m, const Eigen::VectorXd& du);

// "node 7 z" (with the log's node names).
std::string dofName(const SolveLog& log, int node, int component);

// The residuals and increments of the Newton iterations of one increment or time step.
class NewtonTrace {
 public:
  void start() { *this = NewtonTrace(); }
  void residual(double relative_norm) { residuals_.push_back(relative_norm); }
  void increment(const model::Model& m, const Eigen::VectorXd& du);

  // Why it failed, as far as the trace shows, with the dof that moved most in the last
  // iteration: "the residual became NaN after ...", "the iterations diverge (residual 1e-3 ->
  // 4e+2) ...", "the residual stalls at ..." or "the iterations converge too slowly ...".
  // Empty when nothing was recorded.
  std::string diagnosis(const SolveLog& log) const;
  // The residual grows (ends above ten times the least seen) ...
  bool diverging() const;
  // ... or ends above a tenth of where it started: the iterations get nowhere (a finite residual).
  bool lost() const;

 private:
  std::vector<double> residuals_;
  LargestMove last_move_;
};

}  // namespace flexmoor::solve
