#pragma once
// Shape functions of the triangular membrane elements (Appendix A, part 3): Lagrange triangles
// complete to degree 1, 2, 3 (N = 3, 6, 10 nodes) on the reference triangle r, s >= 0,
// r + s <= 1, in the area coordinates of Appendix A, L1 = r, L2 = s, L3 = 1 - r - s.
//
// Node order (the Gmsh / VTK order, so meshes and output need no renumbering): corners
// counter-clockwise, then the edge nodes edge by edge, edges 0-1, 1-2, 2-0, each edge's nodes
// ordered from its first corner to its second, then the centroid (T10):
//   corners: 0 (0, 0) [L3 = 1]   1 (1, 0) [L1 = 1]   2 (0, 1) [L2 = 1]
//   T6:  3 (1/2, 0)   4 (1/2, 1/2)   5 (0, 1/2)
//   T10: 3 (1/3, 0)   4 (2/3, 0)     5 (2/3, 1/3)   6 (1/3, 2/3)   7 (0, 2/3)   8 (0, 1/3)
//        9 (1/3, 1/3)
// Appendix A numbers the same nodes differently: its T6 nodes 1..6 are 1, 2, 0, 4, 5, 3 here and
// its T10 nodes 1..10 are 1, 2, 0, 5, 6, 7, 8, 3, 4, 9.
#include <Eigen/Core>

namespace flexmoor::shape {

template <int N>
struct TriangleShape {
  static_assert(N == 3 || N == 6 || N == 10, "triangular elements have 3, 6 or 10 nodes");
  static constexpr int kDegree = N == 3 ? 1 : (N == 6 ? 2 : 3);  // polynomial degree
  using Values = Eigen::Matrix<double, N, 1>;
  using Derivatives = Eigen::Matrix<double, N, 2>;  // columns d/dr, d/ds

  // Natural coordinates (r, s) of node i, in the order above.
  static Eigen::Vector2d node(int i) {
    const Index k = index(i);
    return {double(k.i1) / kDegree, double(k.i2) / kDegree};
  }

  static Values values(double r, double s) {
    Values M;
    for (int i = 0; i < N; ++i) M(i) = evaluate(i, r, s).value;
    return M;
  }

  static Derivatives derivatives(double r, double s) {
    Derivatives dM;
    for (int i = 0; i < N; ++i) dM.row(i) = evaluate(i, r, s).gradient;
    return dM;
  }

 private:
  // Node i sits at (L3, L1, L2) = (i3, i1, i2) / kDegree, i1 + i2 + i3 = kDegree.
  struct Index {
    int i3, i1, i2;
  };

  static constexpr Index index(int i) {
    constexpr Index t3[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    constexpr Index t6[6] = {{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    constexpr Index t10[10] = {{3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {2, 1, 0}, {1, 2, 0},
                               {0, 2, 1}, {0, 1, 2}, {1, 0, 2}, {2, 0, 1}, {1, 1, 1}};
    if constexpr (N == 3) return t3[i];
    if constexpr (N == 6) return t6[i];
    return t10[i];
  }

  struct Factor {
    double value, derivative;
  };

  // The 1D factor of a node with index m in area coordinate L:
  // l_m(L) = prod_{j < m} (kDegree L - j) / (j + 1), equal to 1 at L = m / kDegree and 0 at L = j /
  // kDegree, j < m.
  static Factor factor(int m, double L) {
    double value = 1.0, derivative = 0.0;
    for (int j = 0; j < m; ++j) {
      const double f = (kDegree * L - j) / (j + 1);
      derivative = derivative * f + value * kDegree / (j + 1);
      value *= f;
    }
    return {value, derivative};
  }

  struct NodeFunction {
    double value;
    Eigen::RowVector2d gradient;
  };

  // M^I = l_i1(L1) l_i2(L2) l_i3(L3); dL1/dr = 1, dL2/ds = 1, dL3/dr = dL3/ds = -1.
  static NodeFunction evaluate(int i, double r, double s) {
    const Index k = index(i);
    const Factor f1 = factor(k.i1, r), f2 = factor(k.i2, s), f3 = factor(k.i3, 1.0 - r - s);
    const double d3 = f1.value * f2.value * f3.derivative;
    return {f1.value * f2.value * f3.value,
            {f1.derivative * f2.value * f3.value - d3, f1.value * f2.derivative * f3.value - d3}};
  }
};

}  // namespace flexmoor::shape
