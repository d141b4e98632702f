#pragma once
// A study member's series.nc (CF-1.8): dimension `time`, `double time(time)` in the case's time
// unit, and one double variable per collect: name over time, with `units`, `long_name`, and the
// window as attributes `window_from` and `window_to` (when bounded). Outside a variable's own
// window its values are _FillValue.
#include <string>
#include <vector>

#include "apps/study/series_recorder.hpp"

namespace flexmoor::app {

struct SeriesData {
  std::vector<double> time;
  struct Variable {
    std::string name, units;
    double from = 0.0, to = 0.0;  // the window; +-infinity when unbounded
    std::vector<double> values;   // NaN where filled
  };
  std::vector<Variable> variables;
};

void writeSeriesFile(const std::string& path, const SeriesRecorder& recorder,
                     const std::string& time_unit);

// The variables `names` of a series.nc; throws std::runtime_error naming what is missing.
SeriesData readSeriesFile(const std::string& path, const std::vector<std::string>& names);

}  // namespace flexmoor::app
