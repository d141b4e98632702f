#pragma once
// Scratch case files for the reader tests: write one, read it, collect what it reports.
#include <string>
#include <vector>

namespace flexmoor::test {

// Writes `text` to a scratch directory as `file_name` and returns its path.
std::string writeCase(const std::string& file_name, const std::string& text);

// The messages of the CaseError that reading `path` throws (empty if it reads).
std::vector<std::string> problems(const std::string& path);

bool anyContains(const std::vector<std::string>& messages, const std::string& part);
std::string joined(const std::vector<std::string>& messages);

}  // namespace flexmoor::test
