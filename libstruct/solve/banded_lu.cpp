#include "libstruct/solve/banded_lu.hpp"

#include <algorithm>
#include <cmath>

// LAPACK (Fortran calling convention; the trailing length is that of the character argument).
extern "C" {
void dgbtrf_(const int* m, const int* n, const int* kl, const int* ku, double* ab, const int* ldab,
             int* ipiv, int* info);
void dgbtrs_(const char* trans, const int* n, const int* kl, const int* ku, const int* nrhs,
             const double* ab, const int* ldab, const int* ipiv, double* b, const int* ldb,
             int* info, std::size_t trans_length);
}

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
  int info = 0;
  dgbtrf_(&n_, &n_, &kl_, &ku_, ab_.data(), &ldab_, pivots_.data(), &info);
  return info == 0;
}

Eigen::VectorXd BandedLu::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  if (n_ == 0) return x;
  const int one = 1;
  int info = 0;
  dgbtrs_("N", &n_, &kl_, &ku_, &one, ab_.data(), &ldab_, pivots_.data(), x.data(), &n_, &info, 1);
  return x;
}

}  // namespace flexmoor::solve
