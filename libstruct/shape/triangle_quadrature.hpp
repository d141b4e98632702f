#pragma once
// Quadrature on the two reference cells of the membrane elements: symmetric Gauss rules on the
// triangle (Dunavant 1985, the Gauss-Hammer family) and the tensor-product Gauss-Legendre rule on
// the square.
#include <Eigen/Core>
#include <vector>

namespace flexmoor::shape {

struct QuadratureRule2D {
  std::vector<Eigen::Vector2d> points;  // natural coordinates, (r, s) or (xi, eta)
  std::vector<double> weights;
  int size() const { return static_cast<int>(points.size()); }
};

constexpr int kMaxTriangleDegree = 14;

// A rule on the reference triangle r, s >= 0, r + s <= 1 (area 1/2: the weights sum to 1/2) that
// integrates every polynomial of total degree <= degree exactly, 1 <= degree <= kMaxTriangleDegree.
// The rules are Dunavant's of degree 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, invariant under the
// permutations of the vertices, with positive weights and every point inside the triangle; a
// request for degree 3, 7 or 11 (whose Dunavant rules have a negative weight or points outside)
// gets the rule of the next degree. Computed once per degree and cached (thread-safe).
const QuadratureRule2D& triangleRule(int degree);

// The n x n tensor product of gaussLegendre(n) on [-1, 1]^2 (the weights sum to 4), exact for
// xi^a eta^b with a, b <= 2n - 1; point i + n j sits at (x_i, x_j) of the 1D rule. 1 <= n <= 32,
// cached like gaussLegendre.
const QuadratureRule2D& gaussLegendreQuad(int n);

}  // namespace flexmoor::shape
