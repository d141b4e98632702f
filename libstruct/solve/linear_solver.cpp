#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {

bool LinearSolver::factorize(const model::SparseMatrix& A) {
  if (method_ == Method::Undecided || (method_ == Method::Banded && !band_lu_.fits(A))) {
    band_lu_.analyzePattern(A);
    method_ = bandIsNarrow(A, band_lu_.band()) ? Method::Banded : Method::Sparse;
  }
  if (method_ == Method::Banded) return band_lu_.factorize(A);
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
  // Eigen's UmfPackLU keeps a reference to the matrix it factorised, and UMFPACK's solve reads it
  // again (iterative refinement): factorise a copy that lives as long as the factorisation, so a
  // caller may pass a temporary or a matrix that goes out of scope before solve().
  lu_matrix_ = A;
  if (!analysed_lu_) {
    lu_.analyzePattern(lu_matrix_);
    analysed_lu_ = true;
  }
  lu_.factorize(lu_matrix_);
  use_lu_ = true;
  return lu_.info() == Eigen::Success;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x;
  solve(b, x);
  return x;
}

void LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (method_ == Method::Banded)
    band_lu_.solve(b, x);
  else if (use_lu_)
    x = lu_.solve(b);
  else
    x = llt_.solve(b);
}

}  // namespace flexmoor::solve
