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

  // The series of a node quantity (position_x, speed, ...) at model node `node`, and of the end
  // tension of element `element` at its first (0) or last (1) end, as the plotting script reads
  // them.
  static std::string nodeSeries(const std::string& quantity, int node) {
    return quantity + "@node=" + std::to_string(node + 1);
  }
  static std::string tensionSeries(int element, int end) {
    return "tension_end@element=" + std::to_string(element + 1) + ",end=" + std::to_string(end + 1);
  }
};

}  // namespace flexmoor::app
