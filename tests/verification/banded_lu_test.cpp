// The band LU of line-like systems (libstruct/solve/banded_lu.hpp) against Eigen's dense LU on
// the same matrices, and the choice LinearSolver makes between it and the sparse solvers.
#include "libstruct/solve/banded_lu.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <vector>

#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor {
namespace {

// A random n x n matrix with nonzeros only within kl below and ku above the diagonal (and a few
// of them left out of the pattern), diagonally weighted by `diagonal`; symmetric when asked.
model::SparseMatrix bandMatrix(int n, int kl, int ku, double diagonal, bool symmetric,
                               unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - ku); i <= std::min(n - 1, j + kl); ++i) {
      if (symmetric && i > j) continue;  // the lower triangle mirrors the upper
      if (i != j && random() % 5 == 0) continue;
      const double a = value(random) + (i == j ? diagonal : 0.0);
      entries.emplace_back(i, j, a);
      if (symmetric && i != j && j - i <= kl) entries.emplace_back(j, i, a);
    }
  model::SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

// Reference: Eigen's PartialPivLU of the dense matrix; tolerance 1e-12 of |x| (both are partial
// pivoting LU in double precision; measured below 1e-14 on these well-conditioned matrices).
TEST(BandedLu, SolvesLikeADenseLu) {
  struct Case {
    int n, kl, ku;
    double diagonal;  // small: pivoting must swap rows
  };
  for (const Case c :
       {Case{1, 0, 0, 2.0}, Case{30, 8, 8, 0.1}, Case{57, 3, 11, 0.0}, Case{200, 8, 8, 4.0}}) {
    const model::SparseMatrix A = bandMatrix(c.n, c.kl, c.ku, c.diagonal, false, 7u + c.n);
    const solve::Band band = solve::bandOf(A);
    EXPECT_LE(band.lower, c.kl);
    EXPECT_LE(band.upper, c.ku);
    solve::BandedLu lu;
    lu.analyzePattern(A);
    ASSERT_TRUE(lu.factorize(A));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(c.n, -1.0, 2.0);
    const Eigen::VectorXd x = lu.solve(b);
    const Eigen::VectorXd reference = Eigen::MatrixXd(A).partialPivLu().solve(b);
    EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm()) << "n " << c.n;
    EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm()) << "n " << c.n;
  }
}

// A line's band matrix with its equations shuffled (a model numbered across its parts, as
// Example 9's tube): the band LU takes it in reverse Cuthill-McKee order, whose band is back
// at the line's (measured 8 below and 9 above the diagonal, the unshuffled line's 8 the
// optimum; bound one above), and solves it as Eigen's dense LU does (tolerance 1e-12 of |x|, as
// above).
TEST(BandedLu, ReordersAShuffledLine) {
  const int n = 120;
  const model::SparseMatrix line = bandMatrix(n, 8, 8, 0.5, false, 13u);
  std::vector<int> shuffle(n);
  for (int i = 0; i < n; ++i) shuffle[i] = i;
  std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(17u));
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(n);
  for (int i = 0; i < n; ++i) P.indices()(i) = shuffle[i];
  const model::SparseMatrix A = (P * line * P.transpose()).eval();
  ASSERT_GT(solve::bandOf(A).lower, 60);
  solve::BandedLu lu;
  lu.analyzePattern(A);
  EXPECT_LE(lu.band().lower, 9);
  EXPECT_LE(lu.band().upper, 10);
  ASSERT_TRUE(lu.factorize(A));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const Eigen::VectorXd reference = Eigen::MatrixXd(A).partialPivLu().solve(b);
  EXPECT_LT((lu.solve(b) - reference).norm(), 1e-12 * reference.norm());
}

// A second factorisation of new values on the same pattern overwrites the first entirely.
TEST(BandedLu, RefactorisesNewValuesOnItsPattern) {
  model::SparseMatrix A = bandMatrix(40, 5, 5, 3.0, true, 3u);
  solve::BandedLu lu;
  lu.analyzePattern(A);
  ASSERT_TRUE(lu.factorize(A));
  A.coeffs() *= -2.5;
  ASSERT_TRUE(lu.factorize(A));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(40);
  EXPECT_LT((A * lu.solve(b) - b).norm(), 1e-12 * b.norm());
}

// A zero column (an unstressed straight cable's transverse dof) is an exact zero pivot: the
// factorisation says singular, as UMFPACK does, so the static solver can regularise it.
TEST(BandedLu, ExactlySingularIsRefused) {
  model::SparseMatrix A = bandMatrix(20, 2, 2, 5.0, true, 11u);
  for (int k = 0; k < A.outerSize(); ++k)
    for (model::SparseMatrix::InnerIterator it(A, k); it; ++it)
      if (it.row() == 6 || it.col() == 6) it.valueRef() = 0.0;
  solve::BandedLu lu;
  lu.analyzePattern(A);
  EXPECT_FALSE(lu.factorize(A));
}

// The choice: a line's matrix (half-bandwidth 8 whatever its length) is banded at every size; a
// matrix whose band is much wider than its rows are full is not, once it is large.
TEST(LinearSolver, ChoosesTheBandForLinesOnly) {
  for (const int n : {30, 3000, 30000}) {
    const model::SparseMatrix line = bandMatrix(n, 8, 8, 20.0, true, 5u);
    solve::LinearSolver solver(solve::MatrixKind::Unsymmetric);
    ASSERT_TRUE(solver.factorize(line));
    EXPECT_TRUE(solver.banded()) << n;
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
    EXPECT_LT((line * solver.solve(b) - b).norm(), 1e-12 * b.norm());
  }
  // A 60 x 50 grid of equations, each coupled with its four neighbours (a membrane's mesh): its
  // band is about 50 in any order (reverse Cuthill-McKee finds no narrower), so the band's
  // 2 n kl^2 = 1.5e7 flops against 200 nnz = 3e6.
  const int rows = 60, columns = 50, n = rows * columns;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 10.0);
    if ((i + 1) % columns != 0)
      entries.emplace_back(i, i + 1, -1.0), entries.emplace_back(i + 1, i, -1.0);
    if (i + columns < n)
      entries.emplace_back(i, i + columns, -1.0), entries.emplace_back(i + columns, i, -1.0);
  }
  model::SparseMatrix wide(n, n);
  wide.setFromTriplets(entries.begin(), entries.end());
  solve::LinearSolver solver;
  ASSERT_TRUE(solver.factorize(wide));
  EXPECT_FALSE(solver.banded());
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  EXPECT_LT((wide * solver.solve(b) - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace flexmoor
