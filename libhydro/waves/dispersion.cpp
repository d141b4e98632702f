#include "libhydro/waves/dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flexmoor::hydro {
namespace {

// tanh(k h) and its complement for h = +inf.
double tanhKh(double k, double depth) { return std::isinf(depth) ? 1.0 : std::tanh(k * depth); }

}  // namespace

double waveNumber(double omega, double depth, double g) {
  if (!(omega > 0.0) || !(depth > 0.0) || !(g > 0.0))
    throw std::invalid_argument("waveNumber: omega, depth and g must be positive");
  const double k_deep = omega * omega / g;
  if (std::isinf(depth) || k_deep * depth > 40.0) return k_deep / tanhKh(k_deep, depth);
  // In x = k h and y = omega^2 h / g: f(x) = x tanh x - y = 0, f increasing for x > 0. Since
  // tanh x <= min(1, x), the root is >= lo = max(y, sqrt(y)), and since tanh is increasing it is
  // <= y / tanh(lo). Newton from Eckart's start y / sqrt(tanh y), kept inside the bracket by
  // bisection.
  const double y = k_deep * depth;
  double lo = std::max(y, std::sqrt(y)), hi = y / std::tanh(lo);
  double x = std::clamp(y / std::sqrt(std::tanh(y)), lo, hi);
  for (int it = 0; it < 60; ++it) {
    const double t = std::tanh(x);
    const double f = x * t - y;
    if (f > 0.0)
      hi = std::min(hi, x);
    else
      lo = std::max(lo, x);
    const double df = t + x * (1.0 - t * t);
    double next = x - f / df;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * x) {
      x = next;
      break;
    }
    x = next;
  }
  return x / depth;
}

double phaseSpeed(double k, double depth, double g) { return std::sqrt(g * tanhKh(k, depth) / k); }

double groupSpeed(double k, double depth, double g) {
  const double c = phaseSpeed(k, depth, g);
  if (std::isinf(depth) || k * depth > 350.0) return 0.5 * c;
  const double two_kh = 2.0 * k * depth;
  return 0.5 * c * (1.0 + two_kh / std::sinh(two_kh));
}

}  // namespace flexmoor::hydro
