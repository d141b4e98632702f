#include "tests/support/case_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/case/case_reader.hpp"
#include "apps/problem/case_error.hpp"

namespace flexmoor::test {

namespace fs = std::filesystem;

std::string shippedCaseText(const std::string& folder_and_name) {
  std::ifstream in(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/" + folder_and_name + ".yaml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string writeCase(const std::string& file_name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "flexmoor-case-reader";
  fs::create_directories(dir);
  const fs::path file = dir / file_name;
  std::ofstream(file) << text;
  return file.string();
}

std::vector<std::string> problems(const std::string& path) {
  try {
    app::readCase(path);
  } catch (const app::CaseError& e) {
    return e.messages();
  }
  return {};
}

bool anyContains(const std::vector<std::string>& messages, const std::string& part) {
  return std::any_of(messages.begin(), messages.end(),
                     [&part](const std::string& m) { return m.find(part) != std::string::npos; });
}

std::string joined(const std::vector<std::string>& messages) {
  std::string s;
  for (const std::string& m : messages) s += m + "\n";
  return s;
}

}  // namespace flexmoor::test
