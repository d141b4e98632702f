#include "apps/case/input/diagnostics.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <utility>

namespace flexmoor::app {

void Diagnostics::error(int line, const std::string& what) {
  if (redirect_) return redirect_->error(line, prefix_ + what);
  problems_.push_back(
      {line, line > 0 ? file_ + ":" + std::to_string(line) + ": " + what : file_ + ": " + what});
}

void Diagnostics::note(int line, const std::string& what) {
  if (redirect_) return redirect_->note(line, prefix_ + what);
  std::string text =
      file_ + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": note: " + what;
  if (std::find(notes_.begin(), notes_.end(), text) == notes_.end())
    notes_.push_back(std::move(text));
}

void Diagnostics::warning(int line, const std::string& what) {
  if (redirect_) return redirect_->warning(line, prefix_ + what);
  warnings_.push_back(file_ + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                      ": warning: " + what);
}

void Diagnostics::error(const YAML::Node& at, const std::string& what) { error(lineOf(at), what); }

std::vector<std::string> Diagnostics::messages() const {
  std::vector<Problem> sorted = problems_;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Problem& a, const Problem& b) { return a.line < b.line; });
  std::vector<std::string> messages;
  for (Problem& p : sorted) messages.push_back(std::move(p.message));
  return messages;
}

void Diagnostics::throwIfAny() const {
  if (!problems_.empty()) throw CaseError(messages());
}

int lineOf(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

}  // namespace flexmoor::app
