#include "libstruct/model/cubic_spline_function.hpp"

#include <algorithm>
#include <stdexcept>

namespace flexmoor::model {
namespace {

// The second derivatives M_i of the not-a-knot spline: the continuity of the first derivative at
// each interior knot, h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1})
// with d_i = (f_{i+1} - f_i) / h_i, and at each end the continuity of the third,
// h_1 M_0 - (h_0 + h_1) M_1 + h_0 M_2 = 0 (and its mirror), which eliminates M_0 and M_{n-1}
// from the first and last equations; the tridiagonal rest by the Thomas algorithm.
std::vector<double> secondDerivatives(const std::vector<double>& t, const std::vector<double>& f) {
  const size_t n = t.size();
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  std::vector<double> h(n - 1), d(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    h[i] = t[i + 1] - t[i];
    d[i] = (f[i + 1] - f[i]) / h[i];
  }
  if (n == 3) {  // the parabola through the three
    m.assign(3, 2.0 * (d[1] - d[0]) / (h[0] + h[1]));
    return m;
  }
  // Unknowns M_1 .. M_{n-2}: sub (a), diagonal (b), super (c), right side (r).
  const size_t k = n - 2;
  std::vector<double> a(k), b(k), c(k), r(k);
  for (size_t j = 0; j < k; ++j) {
    const size_t i = j + 1;
    a[j] = h[i - 1];
    b[j] = 2.0 * (h[i - 1] + h[i]);
    c[j] = h[i];
    r[j] = 6.0 * (d[i] - d[i - 1]);
  }
  // M_0 = ((h_0 + h_1) M_1 - h_0 M_2) / h_1 into the first equation, M_{n-1} likewise the last.
  b[0] += h[0] * (h[0] + h[1]) / h[1];
  c[0] -= h[0] * h[0] / h[1];
  b[k - 1] += h[n - 2] * (h[n - 3] + h[n - 2]) / h[n - 3];
  a[k - 1] -= h[n - 2] * h[n - 2] / h[n - 3];
  for (size_t j = 1; j < k; ++j) {  // forward elimination
    const double w = a[j] / b[j - 1];
    b[j] -= w * c[j - 1];
    r[j] -= w * r[j - 1];
  }
  m[k] = r[k - 1] / b[k - 1];
  for (size_t j = k - 1; j-- > 0;) m[j + 1] = (r[j] - c[j] * m[j + 2]) / b[j];
  m[0] = ((h[0] + h[1]) * m[1] - h[0] * m[2]) / h[1];
  m[n - 1] = ((h[n - 3] + h[n - 2]) * m[n - 2] - h[n - 2] * m[n - 3]) / h[n - 3];
  return m;
}

}  // namespace

CubicSplineFunction::CubicSplineFunction(std::vector<double> times, std::vector<double> values)
    : t_(std::move(times)), f_(std::move(values)) {
  if (t_.empty() || t_.size() != f_.size())
    throw std::invalid_argument("a spline needs as many values as times, at least one");
  if (std::adjacent_find(t_.begin(), t_.end(), std::greater_equal<double>()) != t_.end())
    throw std::invalid_argument("spline times must increase strictly");
  m_ = secondDerivatives(t_, f_);
}

int CubicSplineFunction::interval(double t) const {
  if (t_.size() < 2 || t < t_.front() || t > t_.back()) return -1;
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return std::min(static_cast<int>(it - t_.begin()) - 1, static_cast<int>(t_.size()) - 2);
}

// On [t_i, t_{i+1}], A = (t_{i+1} - t) / h, B = (t - t_i) / h:
//   S = A f_i + B f_{i+1} + ((A^3 - A) M_i + (B^3 - B) M_{i+1}) h^2 / 6,
//   S' = (f_{i+1} - f_i) / h + ((3 B^2 - 1) M_{i+1} - (3 A^2 - 1) M_i) h / 6, S'' = A M_i + B M_{i+1}.
double CubicSplineFunction::value(double t) const {
  const int i = interval(t);
  if (i < 0) return t < t_.front() ? f_.front() : f_.back();
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h, b = 1.0 - a;
  return a * f_[i] + b * f_[i + 1] +
         ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
}

double CubicSplineFunction::rate(double t) const {
  const int i = interval(t);
  if (i < 0) return 0.0;
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h, b = 1.0 - a;
  return (f_[i + 1] - f_[i]) / h +
         ((3.0 * b * b - 1.0) * m_[i + 1] - (3.0 * a * a - 1.0) * m_[i]) * h / 6.0;
}

double CubicSplineFunction::acceleration(double t) const {
  const int i = interval(t);
  if (i < 0) return 0.0;
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h;
  return a * m_[i] + (1.0 - a) * m_[i + 1];
}

}  // namespace flexmoor::model
