#include "apps/study/study_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "apps/output/summary_series.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {
namespace {

double reduce(SummarySpec::Reduction r, const std::vector<double>& t,
              const std::vector<double>& v) {
  SummarySpec spec;
  spec.name = "collect";
  spec.reduction = r;  // over the whole series: the window's points are the only ones kept
  SeriesReduction reduction(spec);
  for (size_t j = 0; j < t.size(); ++j)
    if (!std::isnan(v[j])) reduction.add(t[j], v[j]);
  return reduction.value();
}

}  // namespace

SeriesStatistics seriesStatistics(const std::vector<double>& t, const std::vector<double>& v) {
  if (std::count_if(v.begin(), v.end(), [](double x) { return !std::isnan(x); }) < 2)
    throw std::logic_error("fewer than two points in the window");
  using R = SummarySpec::Reduction;
  SeriesStatistics s;
  s.max = reduce(R::Max, t, v);
  s.min = reduce(R::Min, t, v);
  s.mean = reduce(R::Mean, t, v);
  s.std = reduce(R::Std, t, v);
  s.amplitude = 0.5 * (s.max - s.min);
  return s;
}

std::vector<double> resampled(const std::vector<double>& t, const std::vector<double>& v,
                              double dt) {
  std::vector<double> tt, vv;
  for (size_t j = 0; j < t.size(); ++j)
    if (!std::isnan(v[j])) {
      tt.push_back(t[j]);
      vv.push_back(v[j]);
    }
  std::vector<double> out;
  if (tt.empty()) return out;
  size_t k = 0;
  for (long j = 0;; ++j) {
    const double time = tt.front() + static_cast<double>(j) * dt;
    if (time > tt.back() + 1e-9 * dt) break;
    while (k + 1 < tt.size() && tt[k + 1] < time) ++k;
    if (k + 1 == tt.size()) {
      out.push_back(vv.back());
      continue;
    }
    const double h = tt[k + 1] - tt[k];
    const double w = h > 0.0 ? std::clamp((time - tt[k]) / h, 0.0, 1.0) : 1.0;
    out.push_back(vv[k] + w * (vv[k + 1] - vv[k]));
  }
  return out;
}

double medianStep(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> times, steps;
  for (size_t j = 0; j < t.size(); ++j)
    if (!std::isnan(v[j])) times.push_back(t[j]);
  for (size_t j = 1; j < times.size(); ++j) steps.push_back(times[j] - times[j - 1]);
  if (steps.empty()) return 0.0;
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  return steps[steps.size() / 2];
}

}  // namespace flexmoor::app
