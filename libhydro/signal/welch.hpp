#pragma once
// Welch's estimate of the one-sided power spectral density of a sampled record: segments of
// `segment` samples, each less its mean and under a Hann window w_j = sin^2(pi j / L), overlapping
// by half, their periodograms averaged (FFTW through fft.hpp). The density is per circular
// frequency (unit^2 s / rad), S(omega_k) = 2 |X_k|^2 dt / (2 pi sum w_j^2) at omega_k = 2 pi k /
// (L dt) (the factor 2 not at k = 0 and k = L / 2), so that sum S d omega is the record's variance
// (Parseval) up to the window's leakage.
#include <vector>

namespace flexmoor::signal {

struct SpectralEstimate {
  double d_omega = 0.0;         // bin width 2 pi / (L dt), rad/s
  std::vector<double> omega;    // k d_omega, k = 0 .. L / 2
  std::vector<double> density;  // S(omega_k)
  int segments = 0;             // how many were averaged

  // sum omega^n S d omega over the bins (the end bins by halves).
  double moment(int n) const;
  // The circular frequency of the largest density after a running mean over `smoothing` bins
  // (odd), the bins at the ends left out.
  double peakFrequency(int smoothing) const;
};

// `segment` even, >= 4 and at most record.size(); dt > 0.
SpectralEstimate welch(const std::vector<double>& record, double dt, int segment);

}  // namespace flexmoor::signal
