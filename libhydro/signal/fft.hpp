#pragma once
// The discrete Fourier transform of real series through FFTW (one-sided, unnormalised forward):
//   X_k = sum_j x_j exp(-2 pi i j k / n), k = 0 .. n / 2,
// and its inverse x_j = (1 / n) sum_k X_k exp(2 pi i j k / n) over all k (the other half the
// conjugates). Plans are made with FFTW_ESTIMATE | FFTW_NO_SIMD, so the same series gives the
// same transform to the bit on every x86-64 machine with the same FFTW (no timing-dependent
// planning, no CPU-dependent SIMD kernels), and under a lock, since FFTW's planner is not
// thread-safe (its execution is).
#include <complex>
#include <vector>

namespace flexmoor::signal {

// X_0 .. X_{n/2} of x (n = x.size() >= 1).
std::vector<std::complex<double>> forwardReal(const std::vector<double>& x);

// The real series of length n whose transform begins with X (X.size() == n / 2 + 1):
// inverseReal(forwardReal(x), x.size()) == x to round-off.
std::vector<double> inverseReal(const std::vector<std::complex<double>>& X, int n);

}  // namespace flexmoor::signal
