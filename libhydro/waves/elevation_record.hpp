#pragma once
// The elevation at one point over one repeat period of a sea whose components lie on an FFT grid
// (omega = m 2 pi / T, m an integer: wave_synthesis.hpp's Equal discretisation, or a measured
// record's reconstruction), by one inverse real FFT instead of a sum of cosines per sample:
//   eta(x, t_j) = sum_c a_c cos(psi_c - m_c 2 pi j / M),
//   psi_c = k_c (x cos b_c + y sin b_c) + phi_c, t_j = j T / M, so that
//   eta_j = (1 / M) sum_m X_m exp(2 pi i j m / M), X_m = (M / 2) sum_{c on m} a_c exp(-i psi_c)
// (components of one frequency in several directions add up).
// No front and no ramp (those are not periodic).
#include <Eigen/Core>
#include <vector>

#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

// eta at (x, y) at t_j = j T / samples, j = 0 .. samples - 1. Every component must be on the
// grid (omega T / 2 pi within 1e-9 of an integer m >= 1) and below the Nyquist frequency of the
// samples (2 m < samples); std::invalid_argument otherwise.
std::vector<double> elevationRecord(const std::vector<WaveComponent>& components,
                                    double repeat_period, const Eigen::Vector2d& at, int samples);

}  // namespace flexmoor::hydro
