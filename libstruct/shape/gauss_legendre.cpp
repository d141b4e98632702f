#include "libstruct/shape/gauss_legendre.hpp"

#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

namespace flexmoor::shape {
namespace {

constexpr int kMaxPoints = 32;

// Roots of the Legendre polynomial P_n by Newton's method from Chebyshev-like starting values;
// weights 2 / ((1 - x^2) P_n'(x)^2).
QuadratureRule1D computeRule(int n) {
  QuadratureRule1D rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    rule.points[i] = -x;
    rule.points[n - 1 - i] = x;
    rule.weights[i] = w;
    rule.weights[n - 1 - i] = w;
  }
  return rule;
}

}  // namespace

const QuadratureRule1D& gaussLegendre(int n) {
  if (n < 1 || n > kMaxPoints)
    throw std::invalid_argument("Gauss-Legendre order must be 1.." + std::to_string(kMaxPoints) +
                                " (got " + std::to_string(n) + ")");
  static std::array<QuadratureRule1D, kMaxPoints + 1> cache;
  static std::array<std::once_flag, kMaxPoints + 1> once;
  std::call_once(once[n], [n] { cache[n] = computeRule(n); });
  return cache[n];
}

}  // namespace flexmoor::shape
