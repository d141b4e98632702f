#pragma once
// Direct solvers for the linearised systems. A matrix whose nonzeros lie in a narrow band (a
// mooring line, a chain of elements numbered along it: bandIsNarrow) is factorised by a band LU,
// symmetric or not. Otherwise the symmetric tangent is factorised with CHOLMOD (symbolic
// analysis once per pattern, numeric factorisation per update); when it is not positive definite
// (compression, a limit point) the solver falls back to UMFPACK's LU, which is also the solver
// for non-symmetric systems (follower-pressure load stiffness, motion-dependent loads).
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <memory>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/banded_lu.hpp"

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
  // The same into x, whose storage is reused (the band LU's solve allocates nothing).
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  // Whether the matrices are factorised as banded (decided at the first factorisation).
  bool banded() const { return method_ == Method::Banded; }
  // Entries of the Cholesky factor L after the symbolic analysis (its memory is 12 bytes each:
  // value and row index); 0 before the first factorisation or when banded.
  double factorNonzeros() const {
    // Eigen offers the CHOLMOD common block through a non-const accessor only.
    return analysed_llt_ ? const_cast<decltype(llt_)&>(llt_).cholmod().lnz : 0.0;
  }

 private:
  bool factorizeLu(const model::SparseMatrix& A);
  enum class Method { Undecided, Banded, Sparse };

  MatrixKind kind_;
  Method method_ = Method::Undecided;
  BandedLu band_lu_;
  bool analysed_llt_ = false, analysed_lu_ = false, use_lu_ = false;
  Eigen::CholmodDecomposition<model::SparseMatrix, Eigen::Lower> llt_;
  Eigen::UmfPackLU<model::SparseMatrix> lu_;
  model::SparseMatrix lu_matrix_;  // the matrix lu_ factorised (lu_ refers to it)
};

}  // namespace flexmoor::solve
