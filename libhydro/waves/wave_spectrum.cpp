#include "libhydro/waves/wave_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

// Composite Simpson over [a, b] in n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

// Simpson over [a, b] with steps of at most `step` (an even count, at least 2).
template <class F>
double simpsonFine(F f, double a, double b, double step) {
  if (!(b > a)) return 0.0;
  const int n = 2 * std::max(1, static_cast<int>(std::ceil((b - a) / (2.0 * step))));
  return simpson(f, a, b, n);
}

// int_a^b w^n (alpha + beta w) dw, n >= 0.
double linearMoment(int n, double alpha, double beta, double a, double b) {
  return alpha * (std::pow(b, n + 1) - std::pow(a, n + 1)) / (n + 1) +
         beta * (std::pow(b, n + 2) - std::pow(a, n + 2)) / (n + 2);
}

}  // namespace

WaveSpectrum WaveSpectrum::piersonMoskowitz(double hs, double tp) { return jonswap(hs, tp, 1.0); }

WaveSpectrum WaveSpectrum::jonswap(double hs, double tp, double gamma) {
  if (!(hs > 0.0) || !(tp > 0.0) || !(gamma >= 1.0))
    throw std::invalid_argument("wave spectrum: needs Hs > 0, Tp > 0 and gamma >= 1");
  WaveSpectrum s;
  s.hs_ = hs;
  s.omega_p_ = 2.0 * kPi / tp;
  s.gamma_ = gamma;
  s.scale_ = 1.0;
  s.scale_ = hs * hs / 16.0 / s.moment(0);
  return s;
}

WaveSpectrum WaveSpectrum::table(const std::vector<std::pair<double, double>>& samples) {
  if (samples.size() < 2) throw std::invalid_argument("spectrum table: needs 2 samples or more");
  WaveSpectrum s;
  double largest = 0.0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const auto [w, S] = samples[i];
    if (!(w >= 0.0) || !(S >= 0.0) || (i > 0 && !(w > samples[i - 1].first)))
      throw std::invalid_argument(
          "spectrum table: needs omega >= 0 strictly increasing and S >= 0");
    if (S > largest) {
      largest = S;
      s.omega_p_ = w;
    }
  }
  if (!(largest > 0.0)) throw std::invalid_argument("spectrum table: every S is zero");
  s.samples_ = samples;
  s.hs_ = 4.0 * std::sqrt(s.moment(0));
  return s;
}

WaveSpectrum WaveSpectrum::tablePerHertz(const std::vector<std::pair<double, double>>& f_density) {
  std::vector<std::pair<double, double>> samples;
  for (const auto& [f, S] : f_density) samples.emplace_back(2.0 * kPi * f, S / (2.0 * kPi));
  return table(samples);
}

double WaveSpectrum::shape(double omega) const {
  if (!(omega > 0.0)) return 0.0;
  const double r = omega / omega_p_;
  const double pm = 5.0 / 16.0 * hs_ * hs_ * std::pow(omega_p_, 4) * std::pow(omega, -5.0) *
                    std::exp(-1.25 * std::pow(r, -4.0));
  if (gamma_ == 1.0) return pm;
  const double sigma = omega <= omega_p_ ? 0.07 : 0.09;
  const double peak = std::exp(-0.5 * std::pow((omega - omega_p_) / (sigma * omega_p_), 2));
  return pm * std::pow(gamma_, peak);
}

double WaveSpectrum::density(double omega) const {
  if (!isTable()) return scale_ * shape(omega);
  if (omega < samples_.front().first || omega > samples_.back().first) return 0.0;
  const auto hi = std::upper_bound(samples_.begin(), samples_.end(), omega,
                                   [](double w, const auto& s) { return w < s.first; });
  if (hi == samples_.end()) return samples_.back().second;
  const auto lo = hi - 1;
  const double u = (omega - lo->first) / (hi->first - lo->first);
  return lo->second + u * (hi->second - lo->second);
}

double WaveSpectrum::significantHeight() const { return hs_; }

std::pair<double, double> WaveSpectrum::support() const {
  if (isTable()) return {samples_.front().first, samples_.back().first};
  return {0.0, std::numeric_limits<double>::infinity()};
}

double WaveSpectrum::moment(int n) const {
  if (isTable()) return moment(n, samples_.front().first, samples_.back().first);
  // The spectrum is negligible below 0.3 wp (exp(-5/4 / 0.3^4) ~ 1e-67) and its tail beyond
  // 60 wp holds (60)^-4 / 4 of m0 ~ 2e-8 of it: integrate [0.3 wp, 60 wp] finely and add the
  // w^-5 tail analytically.
  const auto f = [&](double w) { return std::pow(w, n) * density(w); };
  const double a = 0.3 * omega_p_, b = 60.0 * omega_p_;
  double sum = simpson(f, a, 2.0 * omega_p_, 20000) + simpson(f, 2.0 * omega_p_, b, 20000);
  if (n < 4) sum += f(b) * b / (4.0 - n);  // int_b^inf C w^(n-5) = C b^(n-4) / (4 - n)
  return sum;
}

double WaveSpectrum::moment(int n, double lo, double hi) const {
  if (!(lo >= 0.0) || !(hi >= lo)) throw std::invalid_argument("moment: needs 0 <= lo <= hi");
  if (isTable()) {
    if (n < 0) throw std::invalid_argument("moment: a table's moments need n >= 0");
    double sum = 0.0;
    for (size_t i = 1; i < samples_.size(); ++i) {
      const auto [w0, s0] = samples_[i - 1];
      const auto [w1, s1] = samples_[i];
      const double a = std::max(lo, w0), b = std::min(hi, w1);
      if (!(b > a)) continue;
      const double beta = (s1 - s0) / (w1 - w0);
      sum += linearMoment(n, s0 - beta * w0, beta, a, b);
    }
    return sum;
  }
  const auto f = [&](double w) { return std::pow(w, n) * density(w); };
  const double step = omega_p_ / 4000.0, split = std::clamp(omega_p_, lo, hi);
  return simpsonFine(f, lo, split, step) + simpsonFine(f, split, hi, step);
}

}  // namespace flexmoor::hydro
