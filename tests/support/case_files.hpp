#pragma once
// Scratch case files for the reader tests: write one, read it, collect what it reports.
#include <string>
#include <vector>

namespace flexmoor::test {

// The text of a shipped case, `folder/name` under the source's cases/ ("ocean/oc4-semi-surge");
// empty when it cannot be read.
std::string shippedCaseText(const std::string& folder_and_name);

// Writes `text` to a scratch directory as `file_name` and returns its path.
std::string writeCase(const std::string& file_name, const std::string& text);

// The messages of the CaseError that reading `path` throws (empty if it reads).
std::vector<std::string> problems(const std::string& path);

bool anyContains(const std::vector<std::string>& messages, const std::string& part);
std::string joined(const std::vector<std::string>& messages);

}  // namespace flexmoor::test
