#include "tests/support/cli_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace flexmoor::test {

namespace fs = std::filesystem;

CliRun flexmoor(const std::string& args) {
  return command(std::string(FLEXMOOR_BINARY) + " " + args);
}

CliRun command(const std::string& line) {
  char errors[] = "/tmp/flexmoor-cli-stderr-XXXXXX";
  const int fd = mkstemp(errors);
  close(fd);
  const std::string redirected = line + " 2>" + std::string(errors);
  CliRun r{0, "", ""};
  FILE* pipe = popen(redirected.c_str(), "r");
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.errors = readFile(errors);
  r.output += r.errors;
  fs::remove(errors);
  return r;
}

// Width and height are big-endian at bytes 16..23, after the signature and IHDR's header.
std::pair<uint32_t, uint32_t> pngSize(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) return {0, 0};
  const auto word = [&](int at) {
    return uint32_t(header[at]) << 24 | uint32_t(header[at + 1]) << 16 |
           uint32_t(header[at + 2]) << 8 | uint32_t(header[at + 3]);
  };
  return {word(16), word(20)};
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string readSummary(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const std::string suffix = ".summary.json";
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      found.push_back(entry.path());
  }
  EXPECT_EQ(found.size(), 1u) << "summaries in " << dir;
  return found.size() == 1 ? readFile(found[0]) : "";
}

double summaryValue(const std::string& json, const std::string& key) {
  const std::regex pattern("\"" + key + "\"\\s*:\\s*([-+0-9.eE]+)");
  std::smatch m;
  if (!std::regex_search(json, m, pattern)) return std::nan("");
  return std::stod(m[1]);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("flexmoor-cli-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string testName(std::string case_name) {
  for (char& ch : case_name)
    if (ch == '-') ch = '_';
  return case_name;
}

std::string runNamedCase(const std::string& case_name) {
  const fs::path dir = scratch(case_name + "-" + std::to_string(getpid()));
  const CliRun r = flexmoor("run " + case_name + " -o " + dir.string() + " --no-figure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return readFile(dir / (case_name + ".summary.json"));
}

std::vector<std::vector<double>> printedNumbers(const CliRun& r) {
  std::vector<std::vector<double>> lines;
  std::istringstream out(r.output.substr(0, r.output.size() - r.errors.size()));
  for (std::string line; std::getline(out, line);) {
    std::istringstream in(line);
    lines.emplace_back();
    for (double x; in >> x;) lines.back().push_back(x);
  }
  return lines;
}

CliRun runText(const fs::path& dir, const std::string& name, const std::string& text,
               const std::string& options) {
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << text;
  return flexmoor("run " + file.string() + " -o " + dir.string() + options);
}

std::string runCaseText(const std::string& name, const std::string& text) {
  const fs::path dir = scratch(name + "-" + std::to_string(getpid()));
  const CliRun r = runText(dir, name, text, " --no-figure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return readSummary(dir);
}

}  // namespace flexmoor::test
