#pragma once
// A specification a builder cannot put on the model (a line's catenary that does not reach, a
// wall that encloses no liquid): the case file's line that states it (0 for none) and why, the
// message starting with the item's `where`. The case reader reports it at its line; buildCase
// refuses the case with it.
#include <string>

namespace flexmoor::app {

struct SpecError {
  int line = 0;
  std::string message;
};

}  // namespace flexmoor::app
