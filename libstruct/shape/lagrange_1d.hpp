#pragma once
// One-dimensional Lagrange shape functions (Appendix A) on xi in [-1, 1] with N equally spaced
// nodes, numbered along the element: node 0 at xi = -1, node N-1 at xi = +1.
#include <Eigen/Core>

namespace flexmoor::shape {

template <int N>
struct Lagrange1D {
  static_assert(N >= 2 && N <= 4, "cable elements have 2, 3 or 4 nodes");
  using Vector = Eigen::Matrix<double, N, 1>;

  static constexpr double node(int i) { return -1.0 + 2.0 * i / (N - 1); }

  // L^I(xi) = prod_{J != I} (xi - xi_J) / (xi_I - xi_J)
  static Vector values(double xi) {
    Vector L;
    for (int i = 0; i < N; ++i) {
      double v = 1.0;
      for (int j = 0; j < N; ++j)
        if (j != i) v *= (xi - node(j)) / (node(i) - node(j));
      L(i) = v;
    }
    return L;
  }

  // dL^I/dxi = sum_{K != I} 1 / (xi_I - xi_K) prod_{J != I, K} (xi - xi_J) / (xi_I - xi_J)
  static Vector derivatives(double xi) {
    Vector dL;
    for (int i = 0; i < N; ++i) {
      double sum = 0.0;
      for (int k = 0; k < N; ++k) {
        if (k == i) continue;
        double term = 1.0 / (node(i) - node(k));
        for (int j = 0; j < N; ++j)
          if (j != i && j != k) term *= (xi - node(j)) / (node(i) - node(j));
        sum += term;
      }
      dL(i) = sum;
    }
    return dL;
  }
};

}  // namespace flexmoor::shape
