#include "libhydro/signal/fft.hpp"

#include <fftw3.h>

#include <mutex>
#include <stdexcept>

namespace flexmoor::signal {
namespace {

constexpr unsigned kPlanFlags = FFTW_ESTIMATE | FFTW_NO_SIMD;

std::mutex& plannerLock() {
  static std::mutex lock;
  return lock;
}

// A plan made, run once and destroyed; planning and destruction under the planner's lock.
template <class MakePlan>
void runOnce(MakePlan make) {
  fftw_plan plan;
  {
    std::lock_guard<std::mutex> guard(plannerLock());
    plan = make();
  }
  if (!plan) throw std::runtime_error("FFTW could not plan the transform");
  fftw_execute(plan);
  std::lock_guard<std::mutex> guard(plannerLock());
  fftw_destroy_plan(plan);
}

}  // namespace

std::vector<std::complex<double>> forwardReal(const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  if (n < 1) throw std::invalid_argument("forwardReal: an empty series");
  std::vector<double> in = x;  // FFTW's r2c keeps its input, but its signature is not const
  std::vector<std::complex<double>> out(n / 2 + 1);
  runOnce([&] {
    return fftw_plan_dft_r2c_1d(n, in.data(), reinterpret_cast<fftw_complex*>(out.data()),
                                kPlanFlags);
  });
  return out;
}

std::vector<double> inverseReal(const std::vector<std::complex<double>>& X, int n) {
  if (n < 1 || static_cast<int>(X.size()) != n / 2 + 1)
    throw std::invalid_argument("inverseReal: needs n / 2 + 1 coefficients of a series of n");
  std::vector<std::complex<double>> in = X;  // c2r overwrites its input
  std::vector<double> out(n);
  runOnce([&] {
    return fftw_plan_dft_c2r_1d(n, reinterpret_cast<fftw_complex*>(in.data()), out.data(),
                                kPlanFlags);
  });
  for (double& v : out) v /= n;
  return out;
}

}  // namespace flexmoor::signal
