#pragma once
// Sea-state spectra S(omega) (one-sided, length^2 s / rad) and their moments
// m_n = int omega^n S d omega:
//   Pierson-Moskowitz: S = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w / wp)^-4)
//   JONSWAP: S_PM gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)), sigma = 0.07 (w <= wp), 0.09 above,
//            normalised numerically so that m0 = Hs^2 / 16 exactly (DNV's 1 - 0.287 ln gamma is an
//            approximation of that factor).
//   table: samples (omega_i, S_i) at increasing omega >= 0, linear between them, zero outside;
//          its moments exact (a polynomial on each interval). A table of S(f) per hertz at f in
//          hertz is S(omega) = S(f) / (2 pi) at omega = 2 pi f (the same m0).
// The synthesis of a spectrum into components is wave_synthesis.hpp.
#include <utility>
#include <vector>

namespace flexmoor::hydro {

class WaveSpectrum {
 public:
  static WaveSpectrum piersonMoskowitz(double hs, double tp);
  static WaveSpectrum jonswap(double hs, double tp, double gamma);
  // (omega, S(omega)) or (f, S(f)) pairs: at least 2, omega >= 0 strictly increasing, S >= 0,
  // some S > 0 (std::invalid_argument otherwise).
  static WaveSpectrum table(const std::vector<std::pair<double, double>>& omega_density);
  static WaveSpectrum tablePerHertz(const std::vector<std::pair<double, double>>& f_density);

  double density(double omega) const;  // S(omega)
  // The peak: JONSWAP's and Pierson-Moskowitz's wp = 2 pi / Tp, a table's largest sample.
  double peakFrequency() const { return omega_p_; }
  double significantHeight() const;  // 4 sqrt(m0)
  // m_n over [0, inf): numerical to 1e-10 relative for the formulas, exact for a table.
  double moment(int n) const;
  // m_n over [lo, hi] (0 <= lo <= hi): composite Simpson with steps of at most wp / 4000,
  // split at wp (where JONSWAP's sigma changes), for the formulas; exact for a table.
  double moment(int n, double lo, double hi) const;
  // The frequency range a table covers; [0, inf) for the formulas.
  std::pair<double, double> support() const;
  // A table's (omega, S) samples; empty for the formulas.
  const std::vector<std::pair<double, double>>& samples() const { return samples_; }
  bool isTable() const { return !samples_.empty(); }
  // The formulas' peak enhancement gamma (1: Pierson-Moskowitz).
  double peakEnhancement() const { return gamma_; }

 private:
  double shape(double omega) const;  // unnormalised
  double hs_ = 0.0, omega_p_ = 0.0, gamma_ = 1.0, scale_ = 1.0;
  std::vector<std::pair<double, double>> samples_;  // a table's (omega, S)
};

}  // namespace flexmoor::hydro
