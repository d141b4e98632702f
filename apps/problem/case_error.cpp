#include "apps/problem/case_error.hpp"

#include <utility>

namespace flexmoor::app {
namespace {

std::string joinLines(const std::vector<std::string>& messages) {
  std::string text;
  for (const std::string& m : messages) text += (text.empty() ? "" : "\n") + ("flexmoor: " + m);
  return text;
}

}  // namespace

CaseError::CaseError(std::vector<std::string> messages)
    : std::runtime_error(joinLines(messages)), messages_(std::move(messages)) {}

}  // namespace flexmoor::app
