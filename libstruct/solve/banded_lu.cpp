#include "libstruct/solve/banded_lu.hpp"

#include <algorithm>
#include <cmath>

namespace flexmoor::solve {

Band bandOf(const model::SparseMatrix& A) {
  Band band;
  for (int j = 0; j < A.outerSize(); ++j)
    for (model::SparseMatrix::InnerIterator it(A, j); it; ++it) {
      band.lower = std::max(band.lower, static_cast<int>(it.row()) - j);
      band.upper = std::max(band.upper, j - static_cast<int>(it.row()));
    }
  return band;
}

bool bandIsNarrow(const model::SparseMatrix& A, const Band& band) {
  const double flops = 2.0 * A.rows() * band.lower * (band.lower + band.upper + 1.0);
  return flops <= std::max(4e6, 200.0 * A.nonZeros());
}

void BandedLu::analyzePattern(const model::SparseMatrix& A, const Band& band) {
  n_ = static_cast<int>(A.rows());
  kl_ = band.lower;
  ku_ = band.upper;
  ldab_ = 2 * kl_ + ku_ + 1;  // kl extra rows for the fill of the row interchanges
  slot_.clear();
  slot_.reserve(A.nonZeros());
  for (int j = 0; j < A.outerSize(); ++j)
    for (model::SparseMatrix::InnerIterator it(A, j); it; ++it)
      slot_.push_back(kl_ + ku_ + static_cast<int>(it.row()) - j + j * ldab_);
  ab_.assign(static_cast<std::size_t>(ldab_) * n_, 0.0);
  pivots_.assign(n_, 0);
}

bool BandedLu::factorize(const model::SparseMatrix& A) {
  std::fill(ab_.begin(), ab_.end(), 0.0);
  const double* values = A.valuePtr();
  for (std::size_t k = 0; k < slot_.size(); ++k) ab_[slot_[k]] = values[k];
  return factorizeBand();
}

// LAPACK's dgbtf2 (unblocked band LU with partial pivoting, the algorithm dgbtrf runs for bands
// narrower than its block of 32), in its storage: A(i, j) at ab_[kv + i - j + j ldab_], kv = kl +
// ku, the kl rows above holding the fill of the row interchanges. LAPACK does each column's
// pivot search, scaling and rank-1 update through a BLAS call (idamax, dscal, dger, which calls
// daxpy per column): for a half-bandwidth of 8 the calls cost more than their 8 x 16
// multiply-adds, and this loop runs the same arithmetic in half the time (docs/performance.md).
bool BandedLu::factorizeBand() {
  const int kv = kl_ + ku_;
  int ju = 0;  // the last column that the interchanges so far reach
  for (int j = 0; j < n_; ++j) {
    double* column = ab_.data() + static_cast<std::size_t>(j) * ldab_ + kv;  // A(j + i, j)
    const int km = std::min(kl_, n_ - 1 - j);
    int p = 0;
    for (int i = 1; i <= km; ++i)
      if (std::fabs(column[i]) > std::fabs(column[p])) p = i;
    pivots_[j] = j + p;
    if (column[p] == 0.0) return false;  // exactly singular, as dgbtrf's info > 0
    ju = std::max(ju, std::min(j + ku_ + p, n_ - 1));
    if (p != 0)
      for (int c = j; c <= ju; ++c) {
        double* to = ab_.data() + static_cast<std::size_t>(c) * ldab_ + kv - c;  // A(., c)
        std::swap(to[j], to[j + p]);
      }
    const double reciprocal = 1.0 / column[0];
    for (int i = 1; i <= km; ++i) column[i] *= reciprocal;
    for (int c = j + 1; c <= ju; ++c) {
      double* to = ab_.data() + static_cast<std::size_t>(c) * ldab_ + kv - c;
      const double u = to[j];
      if (u == 0.0) continue;
      for (int i = 1; i <= km; ++i) to[j + i] -= u * column[i];
    }
  }
  return true;
}

Eigen::VectorXd BandedLu::solve(const Eigen::VectorXd& b) const {
  // dgbtrs: L y = P b column by column, then U x = y by columns from the last.
  Eigen::VectorXd x = b;
  const int kv = kl_ + ku_;
  for (int j = 0; j < n_; ++j) {
    if (pivots_[j] != j) std::swap(x(j), x(pivots_[j]));
    const double* l = ab_.data() + static_cast<std::size_t>(j) * ldab_ + kv;
    const int km = std::min(kl_, n_ - 1 - j);
    for (int i = 1; i <= km; ++i) x(j + i) -= l[i] * x(j);
  }
  for (int j = n_ - 1; j >= 0; --j) {
    const double* u = ab_.data() + static_cast<std::size_t>(j) * ldab_ + kv - j;  // U(., j)
    x(j) /= u[j];
    for (int i = std::max(0, j - kv); i < j; ++i) x(i) -= u[i] * x(j);
  }
  return x;
}

}  // namespace flexmoor::solve
