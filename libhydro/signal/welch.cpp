#include "libhydro/signal/welch.hpp"

#include <cmath>
#include <stdexcept>

#include "libhydro/signal/fft.hpp"

namespace flexmoor::signal {
namespace {

const double kPi = std::acos(-1.0);

}  // namespace

double SpectralEstimate::moment(int n) const {
  double sum = 0.0;
  const size_t last = density.size() - 1;
  for (size_t k = 0; k <= last; ++k)
    sum += (k == 0 || k == last ? 0.5 : 1.0) * std::pow(omega[k], n) * density[k];
  return sum * d_omega;
}

double SpectralEstimate::peakFrequency(int smoothing) const {
  const int half = smoothing / 2, n = static_cast<int>(density.size());
  if (smoothing < 1 || smoothing % 2 == 0 || n < smoothing + 2)
    throw std::invalid_argument("peakFrequency: needs an odd smoothing narrower than the estimate");
  int best = 1 + half;
  double best_sum = -1.0;
  for (int k = 1 + half; k < n - 1 - half; ++k) {
    double sum = 0.0;
    for (int j = -half; j <= half; ++j) sum += density[k + j];
    if (sum > best_sum) {
      best_sum = sum;
      best = k;
    }
  }
  return omega[best];
}

SpectralEstimate welch(const std::vector<double>& record, double dt, int segment) {
  const int n = static_cast<int>(record.size());
  if (segment < 4 || segment % 2 != 0 || segment > n || !(dt > 0.0))
    throw std::invalid_argument(
        "welch: needs an even segment of 4 samples or more within the "
        "record, and dt > 0");
  std::vector<double> window(segment);
  double window_power = 0.0;
  for (int j = 0; j < segment; ++j) {
    window[j] = std::pow(std::sin(kPi * j / segment), 2);
    window_power += window[j] * window[j];
  }
  SpectralEstimate e;
  e.d_omega = 2.0 * kPi / (segment * dt);
  e.omega.resize(segment / 2 + 1);
  e.density.assign(segment / 2 + 1, 0.0);
  for (int k = 0; k <= segment / 2; ++k) e.omega[k] = k * e.d_omega;
  std::vector<double> piece(segment);
  for (int start = 0; start + segment <= n; start += segment / 2) {
    double mean = 0.0;
    for (int j = 0; j < segment; ++j) mean += record[start + j] / segment;
    for (int j = 0; j < segment; ++j) piece[j] = (record[start + j] - mean) * window[j];
    const auto X = forwardReal(piece);
    for (int k = 0; k <= segment / 2; ++k) e.density[k] += std::norm(X[k]);
    ++e.segments;
  }
  for (int k = 0; k <= segment / 2; ++k) {
    const double one_sided = k == 0 || k == segment / 2 ? 1.0 : 2.0;
    e.density[k] *= one_sided * dt / (2.0 * kPi * window_power * e.segments);
  }
  return e;
}

}  // namespace flexmoor::signal
