#pragma once
// Shape functions of the quadrilateral membrane elements (Appendix A, part 2) on the reference
// square (xi, eta) in [-1, 1]^2: the bilinear Q4 and the serendipity Q8 and Q12 (boundary nodes
// only). Q4 reproduces 1, xi, eta, xi eta; Q8 every quadratic and xi^2 eta, xi eta^2; Q12 every
// cubic and xi^3 eta, xi eta^3.
//
// Node order (that of Gmsh, and of VTK for Q4 and Q8, so meshes and output need no renumbering):
//   corners, counter-clockwise from (-1, -1):
//     0 (-1, -1)   1 (1, -1)   2 (1, 1)   3 (-1, 1)
//   then the mid-side nodes edge by edge, edges 0-1, 1-2, 2-3, 3-0, each edge's nodes ordered
//   from its first corner to its second:
//     Q8:  4 (0, -1)   5 (1, 0)   6 (0, 1)   7 (-1, 0)
//     Q12: 4 (-1/3, -1)   5 (1/3, -1)   6 (1, -1/3)    7 (1, 1/3)
//          8 (1/3, 1)     9 (-1/3, 1)  10 (-1, 1/3)   11 (-1, -1/3)
// Appendix A numbers the same nodes differently: its corners 1..4 are 2, 3, 0, 1 here and its
// Q12 nodes 5..12 are 6, 8, 10, 4, 7, 9, 11, 5.
#include <Eigen/Core>
#include <cmath>

namespace flexmoor::shape {

template <int N>
struct QuadShape {
  static_assert(N == 4 || N == 8 || N == 12, "quadrilateral elements have 4, 8 or 12 nodes");
  using Values = Eigen::Matrix<double, N, 1>;
  using Derivatives = Eigen::Matrix<double, N, 2>;  // columns d/dxi, d/deta

  // Natural coordinates (xi, eta) of node i, in the order above.
  static Eigen::Vector2d node(int i) {
    constexpr double t = 1.0 / 3.0;
    constexpr double q4[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    constexpr double q8[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    constexpr double q12[8][2] = {{-t, -1}, {t, -1}, {1, -t}, {1, t},
                                  {t, 1},   {-t, 1}, {-1, t}, {-1, -t}};
    if (i < 4) return {q4[i][0], q4[i][1]};
    if constexpr (N == 8) return {q8[i - 4][0], q8[i - 4][1]};
    return {q12[i - 4][0], q12[i - 4][1]};
  }

  static Values values(double xi, double eta) {
    Values M;
    for (int i = 0; i < N; ++i) M(i) = evaluate(i, xi, eta).value;
    return M;
  }

  static Derivatives derivatives(double xi, double eta) {
    Derivatives dM;
    for (int i = 0; i < N; ++i) dM.row(i) = evaluate(i, xi, eta).gradient;
    return dM;
  }

 private:
  struct NodeFunction {
    double value;
    Eigen::RowVector2d gradient;
  };

  // M^I and its gradient (Appendix A), for node I at (xi_I, eta_I):
  //   Q4  corner            (1 + xi xi_I)(1 + eta eta_I) / 4
  //   Q8  corner            (1 + xi xi_I)(1 + eta eta_I)(xi xi_I + eta eta_I - 1) / 4
  //       side, xi_I = 0    (1 - xi^2)(1 + eta eta_I) / 2
  //   Q12 corner            (1 + xi xi_I)(1 + eta eta_I)(9 (xi^2 + eta^2) - 10) / 32
  //       side, |eta_I| = 1 9 (1 - xi^2)(1 + 9 xi xi_I)(1 + eta eta_I) / 32
  // and the same with xi and eta exchanged on the other edges. A corner function is the bilinear
  // one times a correction; a side function is a polynomial e(t) along its edge times the blend
  // (1 + n n_I) / 2 across it.
  static NodeFunction evaluate(int i, double xi, double eta) {
    const Eigen::Vector2d p = node(i);
    if (i < 4) {
      const double fx = 1.0 + xi * p.x(), fy = 1.0 + eta * p.y();
      const double b = 0.25 * fx * fy;  // bilinear, Q4
      const Eigen::RowVector2d db(0.25 * p.x() * fy, 0.25 * fx * p.y());
      double c = 1.0;
      Eigen::RowVector2d dc(0.0, 0.0);
      if constexpr (N == 8) {  // (xi xi_I + eta eta_I - 1)
        c = xi * p.x() + eta * p.y() - 1.0;
        dc << p.x(), p.y();
      } else if constexpr (N == 12) {  // (9 (xi^2 + eta^2) - 10) / 8
        c = (9.0 * (xi * xi + eta * eta) - 10.0) / 8.0;
        dc << 9.0 * xi / 4.0, 9.0 * eta / 4.0;
      }
      return {b * c, db * c + b * dc};
    }
    // (t, n): coordinates along and across the edge; t_I, n_I those of the node.
    const bool horizontal = std::abs(p.y()) == 1.0;
    const double t = horizontal ? xi : eta, n = horizontal ? eta : xi;
    const double tI = horizontal ? p.x() : p.y(), nI = horizontal ? p.y() : p.x();
    double e, de;
    if constexpr (N == 8) {  // 1 - t^2
      e = 1.0 - t * t;
      de = -2.0 * t;
    } else {  // 9/16 (1 - t^2)(1 + 9 t t_I)
      e = 9.0 / 16.0 * (1.0 - t * t) * (1.0 + 9.0 * t * tI);
      de = 9.0 / 16.0 * (-2.0 * t * (1.0 + 9.0 * t * tI) + 9.0 * tI * (1.0 - t * t));
    }
    const double g = 0.5 * (1.0 + n * nI), dg = 0.5 * nI;
    const double dt = de * g, dn = e * dg;
    return {e * g, horizontal ? Eigen::RowVector2d(dt, dn) : Eigen::RowVector2d(dn, dt)};
  }
};

}  // namespace flexmoor::shape
