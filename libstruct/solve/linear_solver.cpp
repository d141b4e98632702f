#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {

bool LinearSolver::factorize(const model::SparseMatrix& A) {
  if (kind_ == MatrixKind::Symmetric) {
    if (!analysed_llt_) {
      llt_.analyzePattern(A);
      analysed_llt_ = true;
    }
    llt_.factorize(A);
    if (llt_.info() == Eigen::Success) {
      use_lu_ = false;
      return true;
    }
  }
  return factorizeLu(A);
}

bool LinearSolver::factorizeLu(const model::SparseMatrix& A) {
  if (!analysed_lu_) {
    lu_.analyzePattern(A);
    analysed_lu_ = true;
  }
  lu_.factorize(A);
  use_lu_ = true;
  return lu_.info() == Eigen::Success;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  return use_lu_ ? Eigen::VectorXd(lu_.solve(b)) : Eigen::VectorXd(llt_.solve(b));
}

}  // namespace flexmoor::solve
