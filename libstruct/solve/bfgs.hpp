#pragma once
// Quasi-Newton (BFGS) corrections on top of a factorised tangent K0 (Matthies & Strang): the
// inverse Jacobian is K0^-1 updated by the rank-two terms of every iteration since K0 was
// formed, applied with the two-loop recursion. A pair whose curvature y.s is not positive is
// skipped, which keeps the implied matrix positive definite.
#include <Eigen/Core>
#include <vector>

#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {

class BfgsUpdates {
 public:
  void reset() { pairs_.clear(); }
  // s: the last displacement correction; y = R_before - R_after, the change of the out-of-balance
  // force it caused.
  void add(const Eigen::VectorXd& s, const Eigen::VectorXd& y);
  // du = H R with H the updated inverse of K0.
  Eigen::VectorXd apply(const Eigen::VectorXd& R, const LinearSolver& K0) const;

 private:
  struct Pair {
    Eigen::VectorXd s, y;
    double rho;
  };
  std::vector<Pair> pairs_;
};

}  // namespace flexmoor::solve
