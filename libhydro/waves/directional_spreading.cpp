#include "libhydro/waves/directional_spreading.hpp"

#include <algorithm>
#include <stdexcept>

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

// The energy share of D within beta0 +- w: int_0^w 2 D by Simpson in 2000 intervals (D is smooth
// and, in x = beta - beta0, even).
double within(const CosineSpreading& d, double w) {
  const int n = 2000;
  const double h = w / n;
  const auto f = [&](double x) { return d.density(d.meanHeading() + x); };
  double sum = f(0.0) + f(w);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return 2.0 * sum * h / 3.0;
}

// int_a^b D by Simpson in 200 intervals (one bin).
double binWeight(const CosineSpreading& d, double a, double b) {
  const int n = 200;
  const double h = (b - a) / n;
  double sum = d.density(a) + d.density(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * d.density(a + i * h);
  return sum * h / 3.0;
}

}  // namespace

CosineSpreading::CosineSpreading(double s, double mean_heading) : s_(s), mean_(mean_heading) {
  if (!(s > 0.0)) throw std::invalid_argument("cos-2s spreading: needs s > 0");
  normaliser_ = std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
}

double CosineSpreading::density(double heading) const {
  // beta - beta0 folded into [-pi, pi]: cos^2s(x / 2) = (cos^2(x / 2))^s, even and 2 pi-periodic.
  const double c = std::cos(0.5 * (heading - mean_));
  return normaliser_ * std::pow(c * c, s_);
}

double CosineSpreading::halfWidth(double tail) const {
  // 1 - within(w) falls from 1 at w = 0 to round-off at pi: bisect for where it crosses `tail`.
  double lo = 0.0, hi = kPi;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (1.0 - within(*this, mid) > tail ? lo : hi) = mid;
  }
  return hi;
}

std::vector<Direction> discretise(const CosineSpreading& spreading, int directions) {
  if (directions < 1) throw std::invalid_argument("discretise: needs 1 direction or more");
  if (directions == 1) return {{spreading.meanHeading(), 1.0}};
  const double w = spreading.halfWidth(1e-4), width = 2.0 * w / directions;
  std::vector<Direction> out;
  double total = 0.0;
  for (int j = 0; j < directions; ++j) {
    const double a = spreading.meanHeading() - w + j * width;
    out.push_back({a + 0.5 * width, binWeight(spreading, a, a + width)});
    total += out.back().weight;
  }
  for (Direction& d : out) d.weight /= total;
  return out;
}

}  // namespace flexmoor::hydro
