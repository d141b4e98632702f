// Shape functions of the membrane elements (Appendix A): the quadrilaterals Q4, Q8, Q12 and the
// triangles T3, T6, T10, all through one typed suite. Each element must interpolate (Kronecker
// delta at its nodes), reproduce the polynomials of its space exactly, have derivatives that
// match finite differences, be conforming (the functions of nodes off an edge vanish on it) and
// number its nodes as documented: corners counter-clockwise, then edge nodes edge by edge.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"

namespace flexmoor::test {
namespace {

using shape::QuadShape;
using shape::TriangleShape;

// Monomial x^a y^b, written as (a, b).
using Monomial = std::pair<int, int>;

// What the tests need to know about each element beyond its API: its reference cell, its corner
// vertices in counter-clockwise order, the nodes inside it, the total degree to which its space
// is complete and the monomials of higher degree it also spans.
template <class Shape>
struct Traits;

const std::vector<Eigen::Vector2d> kSquare = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
const std::vector<Eigen::Vector2d> kTriangle = {{0, 0}, {1, 0}, {0, 1}};

template <>
struct Traits<QuadShape<4>> {
  static constexpr const char* name = "Q4";
  static const std::vector<Eigen::Vector2d>& corners() { return kSquare; }
  static constexpr int interior = 0, complete = 1;
  static std::vector<Monomial> extra() { return {{1, 1}}; }
};
template <>
struct Traits<QuadShape<8>> {
  static constexpr const char* name = "Q8";
  static const std::vector<Eigen::Vector2d>& corners() { return kSquare; }
  static constexpr int interior = 0, complete = 2;
  static std::vector<Monomial> extra() { return {{2, 1}, {1, 2}}; }
};
template <>
struct Traits<QuadShape<12>> {
  static constexpr const char* name = "Q12";
  static const std::vector<Eigen::Vector2d>& corners() { return kSquare; }
  static constexpr int interior = 0, complete = 3;
  static std::vector<Monomial> extra() { return {{3, 1}, {1, 3}}; }
};
template <>
struct Traits<TriangleShape<3>> {
  static constexpr const char* name = "T3";
  static const std::vector<Eigen::Vector2d>& corners() { return kTriangle; }
  static constexpr int interior = 0, complete = 1;
  static std::vector<Monomial> extra() { return {}; }
};
template <>
struct Traits<TriangleShape<6>> {
  static constexpr const char* name = "T6";
  static const std::vector<Eigen::Vector2d>& corners() { return kTriangle; }
  static constexpr int interior = 0, complete = 2;
  static std::vector<Monomial> extra() { return {}; }
};
template <>
struct Traits<TriangleShape<10>> {
  static constexpr const char* name = "T10";
  static const std::vector<Eigen::Vector2d>& corners() { return kTriangle; }
  static constexpr int interior = 1, complete = 3;
  static std::vector<Monomial> extra() { return {}; }
};

template <class Shape>
constexpr int nodeCount() {
  return Shape::Values::RowsAtCompileTime;
}

template <class Shape>
bool isTriangle() {
  return Traits<Shape>::corners().size() == 3;
}

// Random points strictly inside the reference cell (fixed seed).
template <class Shape>
std::vector<Eigen::Vector2d> randomPoints(int count) {
  std::mt19937 gen(20240611);
  std::uniform_real_distribution<double> u(-0.999, 0.999);
  std::vector<Eigen::Vector2d> points;
  while (static_cast<int>(points.size()) < count) {
    Eigen::Vector2d p(u(gen), u(gen));
    if (isTriangle<Shape>()) {
      p = (p.array() + 1.0) / 2.0;
      if (p.sum() >= 0.999) continue;
    }
    points.push_back(p);
  }
  return points;
}

// The monomials the element must reproduce: complete to its degree, plus its extras.
template <class Shape>
std::vector<Monomial> spannedMonomials() {
  std::vector<Monomial> m = Traits<Shape>::extra();
  for (int a = 0; a <= Traits<Shape>::complete; ++a)
    for (int b = 0; a + b <= Traits<Shape>::complete; ++b) m.emplace_back(a, b);
  return m;
}

double power(double x, int n) { return n == 0 ? 1.0 : std::pow(x, n); }

// d/dx x^n.
double powerDerivative(double x, int n) { return n == 0 ? 0.0 : n * power(x, n - 1); }

template <class Shape>
class ShapeFunctions : public ::testing::Test {};

using Elements = ::testing::Types<QuadShape<4>, QuadShape<8>, QuadShape<12>, TriangleShape<3>,
                                  TriangleShape<6>, TriangleShape<10>>;

struct ElementName {
  template <class Shape>
  static std::string GetName(int) {
    return Traits<Shape>::name;
  }
};

TYPED_TEST_SUITE(ShapeFunctions, Elements, ElementName);

// sum_I M^I = 1 and sum_I M^I,a = 0 at random points (1e-14).
TYPED_TEST(ShapeFunctions, PartitionOfUnityAndZeroDerivativeSum) {
  for (const Eigen::Vector2d& p : randomPoints<TypeParam>(50)) {
    EXPECT_NEAR(TypeParam::values(p.x(), p.y()).sum(), 1.0, 1e-14);
    const Eigen::RowVector2d dsum = TypeParam::derivatives(p.x(), p.y()).colwise().sum();
    EXPECT_NEAR(dsum(0), 0.0, 1e-13);
    EXPECT_NEAR(dsum(1), 0.0, 1e-13);
  }
}

// M^I(x_J) = delta_IJ (1e-14).
TYPED_TEST(ShapeFunctions, KroneckerDeltaAtNodes) {
  constexpr int N = nodeCount<TypeParam>();
  for (int j = 0; j < N; ++j) {
    const Eigen::Vector2d x = TypeParam::node(j);
    const typename TypeParam::Values M = TypeParam::values(x.x(), x.y());
    for (int i = 0; i < N; ++i)
      EXPECT_NEAR(M(i), i == j ? 1.0 : 0.0, 1e-14) << "M^" << i << " at node " << j;
  }
}

// Analytic derivatives against central differences, step 1e-6 (error ~1e-11; tolerance 1e-8).
TYPED_TEST(ShapeFunctions, DerivativesMatchCentralFiniteDifference) {
  const double h = 1e-6;
  for (const Eigen::Vector2d& p : randomPoints<TypeParam>(20)) {
    using Values = typename TypeParam::Values;
    const typename TypeParam::Derivatives dM = TypeParam::derivatives(p.x(), p.y());
    const Values dxi =
        (TypeParam::values(p.x() + h, p.y()) - TypeParam::values(p.x() - h, p.y())) / (2.0 * h);
    const Values deta =
        (TypeParam::values(p.x(), p.y() + h) - TypeParam::values(p.x(), p.y() - h)) / (2.0 * h);
    EXPECT_LT((dM.col(0) - dxi).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((dM.col(1) - deta).cwiseAbs().maxCoeff(), 1e-8);
  }
}

// Every monomial of the element's space (all of total degree <= its complete degree, plus the
// serendipity or bilinear extras), sampled at the nodes, is interpolated exactly, and so are its
// first derivatives (1e-12).
TYPED_TEST(ShapeFunctions, ReproducesPolynomialsOfItsSpaceExactly) {
  constexpr int N = nodeCount<TypeParam>();
  for (const auto& [a, b] : spannedMonomials<TypeParam>()) {
    Eigen::Matrix<double, N, 1> f;
    for (int i = 0; i < N; ++i)
      f(i) = power(TypeParam::node(i).x(), a) * power(TypeParam::node(i).y(), b);
    for (const Eigen::Vector2d& p : randomPoints<TypeParam>(10)) {
      const double x = p.x(), y = p.y();
      EXPECT_NEAR(TypeParam::values(x, y).dot(f), power(x, a) * power(y, b), 1e-12)
          << "x^" << a << " y^" << b;
      const Eigen::RowVector2d grad = f.transpose() * TypeParam::derivatives(x, y);
      EXPECT_NEAR(grad(0), powerDerivative(x, a) * power(y, b), 1e-11);
      EXPECT_NEAR(grad(1), power(x, a) * powerDerivative(y, b), 1e-11);
    }
  }
}

// The documented order: the corners of the reference cell counter-clockwise, then each edge's
// nodes equally spaced from its first corner to its second, edges in order, then the interior
// node (the centroid of T10).
TYPED_TEST(ShapeFunctions, NodesAreCornersCounterClockwiseThenEdgesInOrder) {
  constexpr int N = nodeCount<TypeParam>();
  const auto& corners = Traits<TypeParam>::corners();
  const int nc = static_cast<int>(corners.size());
  const int per_edge = (N - nc - Traits<TypeParam>::interior) / nc;
  for (int k = 0; k < nc; ++k) EXPECT_EQ(TypeParam::node(k), corners[k]) << "corner " << k;
  for (int e = 0; e < nc; ++e)
    for (int j = 0; j < per_edge; ++j) {
      const int i = nc + e * per_edge + j;
      const Eigen::Vector2d expected =
          corners[e] + (j + 1.0) / (per_edge + 1.0) * (corners[(e + 1) % nc] - corners[e]);
      EXPECT_LT((TypeParam::node(i) - expected).norm(), 1e-15) << "node " << i;
    }
  if (Traits<TypeParam>::interior == 1) {
    EXPECT_LT((TypeParam::node(N - 1) - Eigen::Vector2d(1.0 / 3, 1.0 / 3)).norm(), 1e-15);
  }
}

// Conformity between neighbouring elements: on an edge, only the functions of that edge's nodes
// are non-zero, so the field along a shared edge depends on the shared nodes alone (1e-14).
TYPED_TEST(ShapeFunctions, FunctionsOfNodesOffAnEdgeVanishOnIt) {
  constexpr int N = nodeCount<TypeParam>();
  const auto& corners = Traits<TypeParam>::corners();
  const int nc = static_cast<int>(corners.size());
  for (int e = 0; e < nc; ++e) {
    const Eigen::Vector2d p0 = corners[e], p1 = corners[(e + 1) % nc];
    const Eigen::Vector2d edge = p1 - p0;
    for (const double t : {0.137, 0.5, 0.71}) {
      const Eigen::Vector2d x = p0 + t * edge;
      const typename TypeParam::Values M = TypeParam::values(x.x(), x.y());
      for (int i = 0; i < N; ++i) {
        const Eigen::Vector2d d = TypeParam::node(i) - p0;
        const bool on_edge = std::abs(d.x() * edge.y() - d.y() * edge.x()) < 1e-12;
        if (!on_edge) {
          EXPECT_NEAR(M(i), 0.0, 1e-14) << "M^" << i << " on edge " << e;
        }
      }
    }
  }
}

}  // namespace
}  // namespace flexmoor::test
