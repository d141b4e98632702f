#pragma once
// Gauss-Legendre quadrature on [-1, 1]; an n-point rule integrates polynomials of degree 2n - 1
// exactly.
#include <vector>

namespace flexmoor::shape {

struct QuadratureRule1D {
  std::vector<double> points;
  std::vector<double> weights;
  int size() const { return static_cast<int>(points.size()); }
};

// The n-point rule, 1 <= n <= 32; computed once per n and cached (thread-safe).
const QuadratureRule1D& gaussLegendre(int n);

}  // namespace flexmoor::shape
