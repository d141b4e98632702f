#include "libhydro/signal/extremes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace flexmoor::signal {
namespace {

const double kPi = std::acos(-1.0);
constexpr double kEulerGamma = 0.57721566490153286;

// "extremes: WHAT (got X, expected Y)" with the numbers in the stream's default (%g) style.
[[noreturn]] void refuse(const std::string& what, double got, const std::string& expected) {
  std::ostringstream s;
  s << "extremes: " << what << " (got " << got << ", expected " << expected << ")";
  throw std::invalid_argument(s.str());
}

double mean(const std::vector<double>& x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

}  // namespace

UpcrossingPeaks upcrossingPeaks(const std::vector<double>& record, double dt) {
  if (!(dt > 0.0)) refuse("the time step must be positive", dt, "dt > 0");
  if (record.size() < 2) refuse("the record is too short", record.size(), "2 samples or more");
  UpcrossingPeaks p;
  p.mean = mean(record);
  double first = 0.0, last = 0.0, largest = 0.0;
  int crossings = 0;
  for (size_t i = 1; i < record.size(); ++i) {
    const double a = record[i - 1], b = record[i];
    if (a <= p.mean && b > p.mean) {
      const double t = (static_cast<double>(i - 1) + (p.mean - a) / (b - a)) * dt;
      if (crossings == 0)
        first = t;
      else
        p.peaks.push_back(largest);
      last = t;
      ++crossings;
      largest = b;
    }
    largest = std::max(largest, b);
  }
  if (crossings >= 2) p.zero_upcrossing_period = (last - first) / (crossings - 1);
  return p;
}

WeibullParameters fitWeibull(const std::vector<double>& heights, double tail_from) {
  std::vector<double> h = heights;
  std::sort(h.begin(), h.end());
  if (!h.empty() && !(h.front() > 0.0))
    refuse("a Weibull fit needs positive heights", h.front(), "> 0");
  const double n = static_cast<double>(h.size());
  // Regression of y = ln(-ln(1 - p)) on x = ln h over the fitted points.
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, count = 0.0;
  for (size_t i = 0; i < h.size(); ++i) {
    const double p = static_cast<double>(i + 1) / (n + 1.0);
    if (p < tail_from) continue;
    const double x = std::log(h[i]), y = std::log(-std::log1p(-p));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++count;
  }
  if (count < 2.0) refuse("a Weibull fit needs more heights in its tail", count, ">= 2");
  const double spread = sxx - sx * sx / count;
  if (!(spread > 0.0)) refuse("a Weibull fit needs heights that differ", h.back(), "a spread");
  const double shape = (sxy - sx * sy / count) / spread;
  const double intercept = (sy - shape * sx) / count;
  return {std::exp(-intercept / shape), shape};
}

GumbelParameters fitGumbel(const std::vector<double>& maxima) {
  if (maxima.size() < 2) refuse("a Gumbel fit needs more maxima", maxima.size(), ">= 2");
  const double m = mean(maxima);
  double squares = 0.0;
  for (double x : maxima) squares += (x - m) * (x - m);
  const double s = std::sqrt(squares / static_cast<double>(maxima.size() - 1));
  if (!(s > 0.0)) refuse("a Gumbel fit needs maxima that differ", m, "a spread");
  const double beta = std::sqrt(6.0) * s / kPi;
  return {m - kEulerGamma * beta, beta};
}

ExtremeEstimate estimateExtremes(const std::vector<double>& record, double dt, double duration,
                                 ExtremeFit fit) {
  if (!(duration > 0.0)) refuse("the duration must be positive", duration, "> 0 s");
  const UpcrossingPeaks p = upcrossingPeaks(record, dt);
  const int peaks = static_cast<int>(p.peaks.size());
  if (peaks < kMinimumPeaks)
    refuse(
        "the record is too short for an extreme-value fit: too few peaks between mean "
        "up-crossings",
        peaks, "at least " + std::to_string(kMinimumPeaks));
  ExtremeEstimate e;
  e.mean = p.mean;
  e.zero_upcrossing_period = p.zero_upcrossing_period;
  if (fit == ExtremeFit::Weibull) {
    if (!(duration > p.zero_upcrossing_period))
      refuse("the duration is shorter than the mean zero-up-crossing period", duration, "> Tz (s)");
    std::vector<double> heights;
    for (double x : p.peaks) heights.push_back(x - p.mean);
    e.weibull = fitWeibull(heights, kWeibullTailFrom);
    e.fitted = peaks;
    const double n = duration / p.zero_upcrossing_period;
    e.mpm = p.mean + e.weibull.scale * std::pow(std::log(n), 1.0 / e.weibull.shape);
    return e;
  }
  const auto block = static_cast<size_t>(
      std::max(1.0, std::round(kGumbelBlockPeriods * p.zero_upcrossing_period / dt)));
  const size_t blocks = record.size() / block;
  if (blocks < static_cast<size_t>(kMinimumBlocks))
    refuse("the record is too short for a Gumbel fit: too few blocks of " +
               std::to_string(static_cast<int>(kGumbelBlockPeriods)) + " Tz",
           blocks, "at least " + std::to_string(kMinimumBlocks));
  e.block_length = static_cast<double>(block) * dt;
  if (!(duration >= e.block_length))
    refuse("the duration is shorter than a Gumbel block", duration, ">= the block's length (s)");
  std::vector<double> maxima;
  for (size_t b = 0; b < blocks; ++b)
    maxima.push_back(
        *std::max_element(record.begin() + b * block, record.begin() + (b + 1) * block));
  e.gumbel = fitGumbel(maxima);
  e.fitted = static_cast<int>(blocks);
  e.mpm = e.gumbel.location + e.gumbel.scale * std::log(duration / e.block_length);
  return e;
}

double mostProbableMaximum(const std::vector<double>& record, double dt, double duration,
                           ExtremeFit fit) {
  return estimateExtremes(record, dt, duration, fit).mpm;
}

}  // namespace flexmoor::signal
