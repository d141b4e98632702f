#pragma once
// The statistics of a collected series over its window, time-weighted as a case's summary:
// statistics are (summary_series.hpp, whose SeriesReduction computes them): max and min over the
// points, mean (1/T) integral of q dt and std sqrt((1/T) integral of (q - mean)^2 dt) by the
// trapezoidal rule; amplitude (max - min) / 2. On a constant dt over whole periods,
// q = m + A sin(w t) gives mean m and std A / sqrt(2) to round-off.
#include <vector>

namespace flexmoor::app {

struct SeriesStatistics {
  double max = 0.0, min = 0.0, mean = 0.0, std = 0.0, amplitude = 0.0;
};

// The points (t, v) with v not NaN, t ascending; throws std::logic_error when fewer than two.
SeriesStatistics seriesStatistics(const std::vector<double>& t, const std::vector<double>& v);

// The points of (t, v) with v not NaN, linearly interpolated at t0 + j dt from the first such
// point t0 on, to the last.
std::vector<double> resampled(const std::vector<double>& t, const std::vector<double>& v,
                              double dt);

// The median spacing of the times of the points with v not NaN (0 for fewer than two).
double medianStep(const std::vector<double>& t, const std::vector<double>& v);

}  // namespace flexmoor::app
