#pragma once
#include <string>
#include <vector>

#include "apps/problem/source_location.hpp"

namespace flexmoor::app {

// `figure:` the PNG a run draws of its time series (flexmoor plot): one panel a series, each in
// the plot's VARIABLE@INDEX form with the model's 1-based node and element numbers.
struct FigureSpec {
  // Series: the time series `series`, one panel each; Mooring: the fairlead tension of every
  // line that has an anchor over time and the lines' profiles in their vertical planes over the
  // seabed and under the water line (a spread mooring's figure when the case gives none).
  enum class Kind { Series, Mooring };
  Kind kind = Kind::Series;
  std::vector<std::string> series;
  std::string title;  // empty: the case's title
  SourceLocation where;
};

}  // namespace flexmoor::app
