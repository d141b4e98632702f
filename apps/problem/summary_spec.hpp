#pragma once
#include <limits>
#include <string>
#include <vector>

#include "apps/problem/source_location.hpp"

namespace flexmoor::app {

// A scalar the case promises in summary.json.
struct SummarySpec {
  enum class Quantity {
    Displacement,        // component of a node's displacement
    Position,            // component of a node's current position
    Velocity,            // component of a node's velocity u'
    Speed,               // |u'| at a node
    Reaction,            // component of a support reaction
    ReactionMagnitude,   // |reaction| at a node
    ReactionHorizontal,  // |(reaction_x, reaction_y)| at a node
    LengthOnSeabed,      // length of a line whose weight the seabed carries (evaluateSummary)
    EndTension,          // force on one end point of an element (its nodal force balance)
    MaxTension,          // largest end tension over all elements
    Frequency,           // omega of mode `mode` (1-based) of a modes step, rad/s
    Period,              // 2 pi / omega of that mode, s
    ResultantMax,        // larger principal membrane stress resultant, mean over the element's
                         // integration points (force per current length)
    ResultantMin,        // smaller principal resultant, likewise
    CpuSeconds,          // the process's CPU time (user + system) when the summary is taken, s
  };
  // How the quantity is taken over its step: from the state that closes it, or, in a dynamic
  // step, from the series of its accepted time steps (summary_series.hpp): at a time, or a
  // statistic over the window [from, to].
  enum class Reduction { StepEnd, AtTime, Max, Min, Mean, Std };
  std::string name;
  Quantity quantity = Quantity::Displacement;
  int node = -1;                   // 0-based model node
  int element = -1;                // 0-based model element
  int end = 0;                     // 0 = first node of the element, 1 = last
  int component = 0;               // 0, 1, 2 = x, y, z
  int mode = 0;                    // Frequency: 1-based mode number
  std::vector<int> elements;       // LengthOnSeabed: the line's elements
  double weight_per_length = 0.0;  // LengthOnSeabed: the submerged weight per unstretched length
                                   // of its element at the anchor
  std::vector<double> element_weights;  // LengthOnSeabed: that of each of its elements
  double scale = 1.0;                   // e.g. -1 to report a sag as positive
  int step = -1;                        // 0-based step index; -1 = the last step
  Reduction reduction = Reduction::StepEnd;
  double at = 0.0;  // AtTime: the time, in the run's time (every dynamic step advances it)
  double from = -std::numeric_limits<double>::infinity();  // the window of a statistic; the
  double to = std::numeric_limits<double>::infinity();     // default is the whole step
  std::string unit;  // unit name in the case's system ("ft", "lbf")
  SourceLocation where;
};

}  // namespace flexmoor::app
