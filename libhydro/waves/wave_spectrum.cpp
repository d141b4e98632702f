#include "libhydro/waves/wave_spectrum.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

// A uniform number in [0, 1) from the top 53 bits of one 64-bit draw.
double unit(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

// Composite Simpson over [a, b] in n (even) intervals.
template <class F>
double simpson(F f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
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

double WaveSpectrum::density(double omega) const { return scale_ * shape(omega); }

double WaveSpectrum::moment(int n) const {
  // The spectrum is negligible below 0.3 wp (exp(-5/4 / 0.3^4) ~ 1e-67) and its tail beyond
  // 60 wp holds (60)^-4 / 4 of m0 ~ 2e-8 of it: integrate [0.3 wp, 60 wp] finely and add the
  // w^-5 tail analytically.
  const auto f = [&](double w) { return std::pow(w, n) * density(w); };
  const double a = 0.3 * omega_p_, b = 60.0 * omega_p_;
  double sum = simpson(f, a, 2.0 * omega_p_, 20000) + simpson(f, 2.0 * omega_p_, b, 20000);
  if (n < 4) sum += f(b) * b / (4.0 - n);  // int_b^inf C w^(n-5) = C b^(n-4) / (4 - n)
  return sum;
}

std::vector<WaveComponent> synthesise(const WaveSpectrum& s, const SynthesisOptions& o,
                                      double depth, double g) {
  if (o.components < 1 || !(o.omega_max_ratio > o.omega_min_ratio) || !(o.omega_min_ratio > 0.0))
    throw std::invalid_argument("wave synthesis: needs components >= 1 and 0 < min < max");
  std::mt19937_64 engine(o.seed);
  const double w0 = o.omega_min_ratio * s.peakFrequency();
  const double dw = (o.omega_max_ratio - o.omega_min_ratio) * s.peakFrequency() / o.components;
  std::vector<WaveComponent> components;
  components.reserve(o.components);
  for (int i = 0; i < o.components; ++i) {
    const double offset = o.jitter ? unit(engine) : 0.5;
    const double phase = 2.0 * kPi * unit(engine);
    WaveComponent c;
    c.omega = w0 + (i + offset) * dw;
    c.amplitude = std::sqrt(2.0 * s.density(c.omega) * dw);
    c.k = waveNumber(c.omega, depth, g);
    c.heading = o.heading;
    c.phase = phase;
    components.push_back(c);
  }
  return components;
}

}  // namespace flexmoor::hydro
