#pragma once
// Where in a case file something was given, for the messages about it.
#include <string>

namespace flexmoor::app {

struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based
};

}  // namespace flexmoor::app
