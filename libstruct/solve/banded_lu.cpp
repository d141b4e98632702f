#include "libstruct/solve/banded_lu.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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

Band bandOf(const model::SparseMatrix& A, const std::vector<int>& position) {
  Band band;
  for (int j = 0; j < A.outerSize(); ++j)
    for (model::SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const int offset = position[it.row()] - position[j];
      band.lower = std::max(band.lower, offset);
      band.upper = std::max(band.upper, -offset);
    }
  return band;
}

namespace {

// The graph of A + A^T: the equations each one is coupled with, itself left out.
std::vector<std::vector<int>> couplings(const model::SparseMatrix& A) {
  std::vector<std::vector<int>> adjacent(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (model::SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (it.row() != j) {
        adjacent[it.row()].push_back(j);
        adjacent[j].push_back(static_cast<int>(it.row()));
      }
  for (auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return adjacent;
}

// Breadth-first level structure of the part of the graph not yet `placed`, from `root`: the
// equations in level order, and where the last level begins. `seen` marks them with `stamp`.
struct Levels {
  std::vector<int> order;
  int depth = 0;
  std::size_t last_begin = 0;
};
void levelsFrom(const std::vector<std::vector<int>>& adjacent, const std::vector<char>& placed,
                int root, std::vector<int>& seen, int stamp, Levels& levels) {
  levels.order.assign(1, root);
  levels.depth = 0;
  levels.last_begin = 0;
  seen[root] = stamp;
  for (std::size_t begin = 0, end = 1; begin < end; begin = end, end = levels.order.size()) {
    levels.last_begin = begin;
    for (std::size_t k = begin; k < end; ++k)
      for (const int a : adjacent[levels.order[k]])
        if (!placed[a] && seen[a] != stamp) {
          seen[a] = stamp;
          levels.order.push_back(a);
        }
    if (levels.order.size() > end) ++levels.depth;
  }
}

}  // namespace

std::vector<int> reverseCuthillMcKee(const model::SparseMatrix& A) {
  const int n = static_cast<int>(A.rows());
  const std::vector<std::vector<int>> adjacent = couplings(A);
  const auto degree = [&](int i) { return adjacent[i].size(); };
  const auto by_degree = [&](int a, int b) { return degree(a) < degree(b); };
  std::vector<char> placed(n, 0);
  std::vector<int> seen(n, -1), order;
  order.reserve(n);
  Levels levels;
  int stamp = 0;
  for (int first = 0; first < n; ++first) {
    if (placed[first]) continue;
    // A pseudo-peripheral root of this connected part: from its equation of least degree, the
    // least-degree equation of the last level, as long as that deepens the level structure.
    levelsFrom(adjacent, placed, first, seen, stamp++, levels);
    int root = *std::min_element(levels.order.begin(), levels.order.end(), by_degree);
    levelsFrom(adjacent, placed, root, seen, stamp++, levels);
    for (;;) {
      const int candidate = *std::min_element(levels.order.begin() + levels.last_begin,
                                              levels.order.end(), by_degree);
      const int depth = levels.depth;
      levelsFrom(adjacent, placed, candidate, seen, stamp++, levels);
      if (levels.depth <= depth) break;
      root = candidate;
    }
    // Cuthill-McKee from the root: breadth first, each equation's new neighbours by degree.
    const std::size_t begin = order.size();
    order.push_back(root);
    placed[root] = 1;
    for (std::size_t k = begin; k < order.size(); ++k) {
      const std::size_t next = order.size();
      for (const int a : adjacent[order[k]])
        if (!placed[a]) {
          placed[a] = 1;
          order.push_back(a);
        }
      std::stable_sort(order.begin() + next, order.end(), by_degree);
    }
  }
  std::vector<int> position(n);
  for (int k = 0; k < n; ++k) position[order[k]] = n - 1 - k;
  return position;
}

bool bandIsNarrow(const model::SparseMatrix& A, const Band& band) {
  const double flops = 2.0 * A.rows() * band.lower * (band.lower + band.upper + 1.0);
  return flops <= std::max(4e6, 200.0 * A.nonZeros());
}

void BandedLu::analyzePattern(const model::SparseMatrix& A) {
  n_ = static_cast<int>(A.rows());
  // Flops of the band LU, 2 n kl (kl + ku + 1): the reordering is taken when it saves some.
  const auto cost = [](const Band& b) { return b.lower * (b.lower + b.upper + 1.0); };
  band_ = bandOf(A);
  position_ = reverseCuthillMcKee(A);
  const Band reordered = bandOf(A, position_);
  if (cost(reordered) < cost(band_))
    band_ = reordered;
  else
    position_.clear();
  kl_ = band_.lower;
  ku_ = band_.upper;
  ldab_ = 2 * kl_ + ku_ + 1;  // kl extra rows for the fill of the row interchanges
  const auto at = [&](int i) { return position_.empty() ? i : position_[i]; };
  slot_.clear();
  slot_.reserve(A.nonZeros());
  for (int j = 0; j < A.outerSize(); ++j)
    for (model::SparseMatrix::InnerIterator it(A, j); it; ++it)
      slot_.push_back(kl_ + ku_ + at(static_cast<int>(it.row())) - at(j) + at(j) * ldab_);
  ab_.clear();  // allocated by the first factorisation: a band too wide to be used costs nothing
  pivots_.assign(n_, 0);
}

bool BandedLu::factorize(const model::SparseMatrix& A) {
  ab_.assign(static_cast<std::size_t>(ldab_) * n_, 0.0);
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
  Eigen::VectorXd x;
  solve(b, x);
  return x;
}

void BandedLu::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (position_.empty()) {
    x = b;
    solveBand(x.data());
    return;
  }
  permuted_.resize(n_);
  for (int i = 0; i < n_; ++i) permuted_[position_[i]] = b(i);
  solveBand(permuted_.data());
  x.resize(n_);
  for (int i = 0; i < n_; ++i) x(i) = permuted_[position_[i]];
}

void BandedLu::solveBand(double* x) const {
  // dgbtrs: L y = P b column by column, then U x = y by columns from the last.
  const int kv = kl_ + ku_;
  for (int j = 0; j < n_; ++j) {
    if (pivots_[j] != j) std::swap(x[j], x[pivots_[j]]);
    const double* l = ab_.data() + static_cast<std::size_t>(j) * ldab_ + kv;
    const int km = std::min(kl_, n_ - 1 - j);
    for (int i = 1; i <= km; ++i) x[j + i] -= l[i] * x[j];
  }
  for (int j = n_ - 1; j >= 0; --j) {
    const double* u = ab_.data() + static_cast<std::size_t>(j) * ldab_ + kv - j;  // U(., j)
    x[j] /= u[j];
    for (int i = std::max(0, j - kv); i < j; ++i) x[i] -= u[i] * x[j];
  }
}

}  // namespace flexmoor::solve
