// Quadrature on the membrane reference cells: the symmetric (Dunavant) triangle rules and the
// tensor-product Gauss-Legendre rule on the square. Exactness is checked monomial by monomial
// against closed forms, so a slip in a transcribed table cannot pass.
#include "libstruct/shape/triangle_quadrature.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace flexmoor::test {
namespace {

using shape::gaussLegendreQuad;
using shape::kMaxTriangleDegree;
using shape::QuadratureRule2D;
using shape::triangleRule;

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

double power(double x, int n) { return n == 0 ? 1.0 : std::pow(x, n); }

double integrate(const QuadratureRule2D& rule, int a, int b) {
  double sum = 0.0;
  for (int q = 0; q < rule.size(); ++q)
    sum += rule.weights[q] * power(rule.points[q].x(), a) * power(rule.points[q].y(), b);
  return sum;
}

// On the reference triangle, integral of r^a s^b = a! b! / (a + b + 2)!. Every rule, for every
// requested degree 1..14, integrates every monomial of total degree <= that degree to 1e-14
// relative (the sums are of positive terms, so rounding stays relative).
TEST(TriangleQuadrature, IntegratesEveryMonomialUpToItsDegreeExactly) {
  for (int degree = 1; degree <= kMaxTriangleDegree; ++degree) {
    const QuadratureRule2D& rule = triangleRule(degree);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b) {
        const double exact = factorial(a) * factorial(b) / factorial(a + b + 2);
        EXPECT_NEAR(integrate(rule, a, b), exact, 1e-14 * exact)
            << "degree " << degree << ", r^" << a << " s^" << b;
      }
  }
}

// The weights add up to the area of the reference triangle, 1/2.
TEST(TriangleQuadrature, WeightsSumToReferenceArea) {
  for (int degree = 1; degree <= kMaxTriangleDegree; ++degree) {
    const QuadratureRule2D& rule = triangleRule(degree);
    double sum = 0.0;
    for (const double w : rule.weights) sum += w;
    EXPECT_NEAR(sum, 0.5, 1e-15) << "degree " << degree;
  }
}

// No negative weight and no point on or outside the boundary, so every rule is safe for
// positive-definite mass matrices and for fields defined only inside the element.
TEST(TriangleQuadrature, WeightsArePositiveAndPointsInterior) {
  for (int degree = 1; degree <= kMaxTriangleDegree; ++degree) {
    const QuadratureRule2D& rule = triangleRule(degree);
    for (int q = 0; q < rule.size(); ++q) {
      const Eigen::Vector2d p = rule.points[q];
      EXPECT_GT(rule.weights[q], 0.0) << "degree " << degree << ", point " << q;
      EXPECT_GT(std::min({p.x(), p.y(), 1.0 - p.x() - p.y()}), 0.0)
          << "degree " << degree << ", point " << q;
    }
  }
}

// The point set with its weights is mapped onto itself by the vertex permutations (r, s) ->
// (s, r) and (r, s) -> (1 - r - s, r): no corner of an element is favoured.
TEST(TriangleQuadrature, RulesAreInvariantUnderVertexPermutations) {
  auto contains = [](const QuadratureRule2D& rule, const Eigen::Vector2d& p, double w) {
    for (int q = 0; q < rule.size(); ++q)
      if ((rule.points[q] - p).norm() < 1e-14 && std::abs(rule.weights[q] - w) < 1e-15) return true;
    return false;
  };
  for (int degree = 1; degree <= kMaxTriangleDegree; ++degree) {
    const QuadratureRule2D& rule = triangleRule(degree);
    for (int q = 0; q < rule.size(); ++q) {
      const double r = rule.points[q].x(), s = rule.points[q].y(), w = rule.weights[q];
      EXPECT_TRUE(contains(rule, {s, r}, w)) << "degree " << degree << ", point " << q;
      EXPECT_TRUE(contains(rule, {1.0 - r - s, r}, w)) << "degree " << degree << ", point " << q;
    }
  }
}

// Point counts of Dunavant's rules; degrees 3, 7 and 11 take the next rule.
TEST(TriangleQuadrature, UsesTheSmallestPositiveInteriorDunavantRule) {
  const std::vector<int> points = {1, 3, 6, 6, 7, 12, 16, 16, 19, 25, 33, 33, 37, 42};
  for (int degree = 1; degree <= kMaxTriangleDegree; ++degree)
    EXPECT_EQ(triangleRule(degree).size(), points[degree - 1]) << "degree " << degree;
}

TEST(TriangleQuadrature, RejectsUnsupportedDegree) {
  EXPECT_THROW(triangleRule(0), std::invalid_argument);
  EXPECT_THROW(triangleRule(kMaxTriangleDegree + 1), std::invalid_argument);
}

// On [-1, 1]^2, integral of xi^a eta^b = 2/(a+1) 2/(b+1) for a, b even, else 0. The n x n rule
// is exact for a, b <= 2n - 1 (1e-14).
TEST(QuadQuadrature, TensorGaussLegendreIntegratesMonomialsExactly) {
  auto exact1d = [](int a) { return a % 2 ? 0.0 : 2.0 / (a + 1); };
  for (int n = 1; n <= 8; ++n) {
    const QuadratureRule2D& rule = gaussLegendreQuad(n);
    ASSERT_EQ(rule.size(), n * n);
    for (int a = 0; a <= 2 * n - 1; ++a)
      for (int b = 0; b <= 2 * n - 1; ++b)
        EXPECT_NEAR(integrate(rule, a, b), exact1d(a) * exact1d(b), 1e-14)
            << n << " x " << n << " points, xi^" << a << " eta^" << b;
  }
}

// Beyond its degree the rule is no longer exact: xi^2n is integrated with an error, which
// confirms the test above would see a rule of too low an order.
TEST(QuadQuadrature, TensorGaussLegendreIsNotExactBeyondItsDegree) {
  for (int n = 1; n <= 8; ++n)
    EXPECT_GT(std::abs(integrate(gaussLegendreQuad(n), 2 * n, 0) - 4.0 / (2 * n + 1)), 1e-6)
        << n << " x " << n << " points";
}

TEST(QuadQuadrature, RejectsUnsupportedOrder) {
  EXPECT_THROW(gaussLegendreQuad(0), std::invalid_argument);
  EXPECT_THROW(gaussLegendreQuad(33), std::invalid_argument);
}

}  // namespace
}  // namespace flexmoor::test
