#pragma once
// Sea-state spectra S(omega) (one-sided, m^2 s / rad) and their synthesis into linear wave
// components with seeded random phases, so that an irregular sea is a Sea with many components.
//   Pierson-Moskowitz: S = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w / wp)^-4)
//   JONSWAP: S_PM gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)), sigma = 0.07 (w <= wp), 0.09 above,
//            normalised numerically so that m0 = Hs^2 / 16 exactly (DNV's 1 - 0.287 ln gamma is an
//            approximation of that factor).
#include <cstdint>
#include <vector>

#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

class WaveSpectrum {
 public:
  static WaveSpectrum piersonMoskowitz(double hs, double tp);
  static WaveSpectrum jonswap(double hs, double tp, double gamma);

  double density(double omega) const;  // S(omega)
  double peakFrequency() const { return omega_p_; }
  double significantHeight() const { return hs_; }
  // Spectral moment m_n = int omega^n S d omega (numerical, to 1e-10 relative).
  double moment(int n) const;

 private:
  double shape(double omega) const;  // unnormalised
  double hs_ = 0.0, omega_p_ = 0.0, gamma_ = 1.0, scale_ = 1.0;
};

struct SynthesisOptions {
  int components = 200;
  double omega_min_ratio = 0.5;  // band [ratio_min wp, ratio_max wp]
  double omega_max_ratio = 4.0;
  uint64_t seed = 1;
  bool jitter = true;  // frequencies drawn uniformly within their bins (no exact repeat period)
  double heading = 0.0;
};

// Components a_i cos(k_i x - w_i t + phi_i) with a_i = sqrt(2 S(w_i) dw), random phases from a
// 64-bit Mersenne Twister with the given seed, taken bit by bit (not through a standard-library
// distribution), so that a seed gives the same sea to the last bit on every platform.
std::vector<WaveComponent> synthesise(const WaveSpectrum& s, const SynthesisOptions& o,
                                      double depth, double g);

}  // namespace flexmoor::hydro
