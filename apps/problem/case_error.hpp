#pragma once
// The error raised when a case's input is wrong: every problem found, each a message
// `FILE:LINE: what is wrong (got X, expected Y)` (apps/case/input/diagnostics.hpp collects them
// while a case or study file is read). The command, the C API and a study's members report it as
// bad input.
#include <stdexcept>
#include <string>
#include <vector>

namespace flexmoor::app {

// Every problem of one case file; what() is one line per problem, each prefixed "flexmoor: ".
class CaseError : public std::runtime_error {
 public:
  explicit CaseError(std::vector<std::string> messages);
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

}  // namespace flexmoor::app
