#pragma once
// LU with partial pivoting of a sparse matrix whose nonzeros lie in a narrow band about the
// diagonal: LAPACK's band algorithm (dgbtf2 / dgbtrs) in LAPACK's band storage, written out
// (banded_lu.cpp says why). A mooring line numbered from anchor to
// fairlead is such a matrix: an L3 line couples each node with the two on either side, so its
// half-bandwidth is 8 whatever its length, and n (kl + ku) flops factorise it. A general sparse
// LU spends more on its pivot search and memory than on that arithmetic (docs/performance.md).
// A model numbered otherwise (Example 9's tube: membranes and moorings, half-bandwidth 55 of 80
// equations) is factorised in the reverse Cuthill-McKee order of its equations when that band
// is narrower.
#include <vector>

#include "libstruct/model/assembler.hpp"

namespace flexmoor::solve {

// The half-bandwidths of a square sparse pattern: kl below the diagonal, ku above.
struct Band {
  int lower = 0, upper = 0;
};
Band bandOf(const model::SparseMatrix& A);
// The same with equation i moved to position[i] (a permutation of 0 .. n - 1).
Band bandOf(const model::SparseMatrix& A, const std::vector<int>& position);

// Reverse Cuthill-McKee (George and Liu, Computer Solution of Large Sparse Positive Definite
// Systems, 1981, section 4.3) on the pattern of A + A^T: position[i] of equation i, each
// connected part started from a pseudo-peripheral equation and ordered breadth first by
// increasing degree, the whole reversed.
std::vector<int> reverseCuthillMcKee(const model::SparseMatrix& A);

// Whether a band factorisation of A is cheaper than a general sparse one: its flops,
// 2 n kl (kl + ku + 1), within a small multiple of the nonzeros (a chain-like structure, whose
// band holds little more than its fill) or too few to matter.
bool bandIsNarrow(const model::SparseMatrix& A, const Band& band);

class BandedLu {
 public:
  // Sets up the band storage for A's pattern, once per pattern: in the equations' own order, or
  // in reverse Cuthill-McKee order when that takes fewer flops (band() is the band used).
  void analyzePattern(const model::SparseMatrix& A);
  const Band& band() const { return band_; }
  // Whether A has the dimensions and number of nonzeros of the pattern analysed.
  bool fits(const model::SparseMatrix& A) const {
    return A.rows() == n_ && A.cols() == n_ &&
           A.nonZeros() == static_cast<Eigen::Index>(slot_.size());
  }
  // Numeric factorisation of A, on the pattern analyzePattern saw. Returns false when A is
  // singular: a pivot exactly zero (as UMFPACK tells; a nearly singular matrix, the tangent at a
  // limit point that arc length passes, still factorises).
  bool factorize(const model::SparseMatrix& A);
  // x = A^-1 b (the second into x, whose storage is reused).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

 private:
  int n_ = 0, kl_ = 0, ku_ = 0, ldab_ = 1;
  Band band_;
  std::vector<int> position_;  // equation i is row and column position_[i]; empty: i itself
  std::vector<int> slot_;      // per nonzero of A (in A's storage order), its place in ab_
  std::vector<double> ab_;     // LAPACK band storage, (2 kl + ku + 1) x n, column-major
  std::vector<int> pivots_;    // row j was interchanged with row pivots_[j] (0-based)
  mutable std::vector<double> permuted_;  // the right-hand side in the band's order, reused

  bool factorizeBand();
  // The band solve of the permuted system in place.
  void solveBand(double* x) const;
};

}  // namespace flexmoor::solve
