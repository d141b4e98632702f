#pragma once
// Sparse direct solvers for the linearised systems. The symmetric tangent is factorised with
// CHOLMOD (symbolic analysis once per pattern, numeric factorisation per update); when it is not
// positive definite (compression, a limit point) the solver falls back to UMFPACK's LU, which is
// also the solver for non-symmetric systems (follower-pressure load stiffness).
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <memory>

#include "libstruct/model/assembler.hpp"

namespace flexmoor::solve {

enum class MatrixKind { Symmetric, Unsymmetric };

class LinearSolver {
 public:
  // CHOLMOD's own printing is off: a matrix that is not positive definite is an expected event
  // here (the solver falls back to LU), reported through the return value, not on stderr.
  explicit LinearSolver(MatrixKind kind = MatrixKind::Symmetric) : kind_(kind) {
    llt_.cholmod().print = 0;
  }

  // Numeric factorisation of A (the symbolic analysis is done on the first call). Returns false
  // when A is singular.
  bool factorize(const model::SparseMatrix& A);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // True when the last factorisation needed LU (the matrix was not positive definite).
  bool usedLu() const { return use_lu_; }
  // Entries of the Cholesky factor L after the symbolic analysis (its memory is 12 bytes each:
  // value and row index); 0 before the first factorisation.
  double factorNonzeros() const {
    // Eigen offers the CHOLMOD common block through a non-const accessor only.
    return analysed_llt_ ? const_cast<decltype(llt_)&>(llt_).cholmod().lnz : 0.0;
  }

 private:
  bool factorizeLu(const model::SparseMatrix& A);

  MatrixKind kind_;
  bool analysed_llt_ = false, analysed_lu_ = false, use_lu_ = false;
  Eigen::CholmodDecomposition<model::SparseMatrix, Eigen::Lower> llt_;
  Eigen::UmfPackLU<model::SparseMatrix> lu_;
  model::SparseMatrix lu_matrix_;  // the matrix lu_ factorised (lu_ refers to it)
};

}  // namespace flexmoor::solve
