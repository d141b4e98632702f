#pragma once
#include <string>
#include <vector>

namespace flexmoor::app {

// A named line of the case (`lines:`, a multi-segment line and its segments), start to end.
struct CaseLine {
  // A mooring line's anchor end (its fairlead is the other end): `anchor: start | end`.
  enum class Anchor { None, Start, End };
  std::string name;
  std::vector<int> nodes;     // 0-based model nodes, start to end
  std::vector<int> elements;  // 0-based model elements, start to end
  std::string segment_of;     // the multi-segment line it is a segment of, "" for none
  Anchor anchor = Anchor::None;
};

}  // namespace flexmoor::app
