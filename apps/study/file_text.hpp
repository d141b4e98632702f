#pragma once
// A file's whole text, for the study's small files (its base case, a member's markers and logs);
// empty when the file cannot be read.
#include <fstream>
#include <iterator>
#include <string>

namespace flexmoor::app {

inline std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace flexmoor::app
