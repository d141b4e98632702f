#include "apps/run/case_outputs.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "apps/output/atomic_output.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool allDigits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char ch) { return std::isdigit(ch) != 0; });
}

// n of "<case>-<n>.vtk"; nothing for any other name.
std::optional<int> vtkStep(const std::string& file, const std::string& case_name) {
  const std::string prefix = case_name + "-", suffix = ".vtk";
  if (file.size() <= prefix.size() + suffix.size() || !startsWith(file, prefix) ||
      file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string digits =
      file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
  if (!allDigits(digits) || digits[0] == '0' || digits.size() > 9) return std::nullopt;
  return std::stoi(digits);
}

// ".<output>.tmp-PID-K" of writeFileAtomically, for a VTK or summary file of the case.
bool isTemporary(const std::string& file, const std::string& case_name) {
  const size_t tmp = file.rfind(".tmp-");
  if (tmp == std::string::npos || file.empty() || file[0] != '.') return false;
  const std::string output = file.substr(1, tmp - 1), tail = file.substr(tmp + 5);
  const size_t dash = tail.find('-');
  if (dash == std::string::npos || !allDigits(tail.substr(0, dash)) ||
      !allDigits(tail.substr(dash + 1)))
    return false;
  return output == case_name + ".summary.json" || vtkStep(output, case_name).has_value();
}

}  // namespace

std::string defaultOutputDirectory(const std::string& case_name) {
  return (fs::path("results") / case_name).string();
}

CaseOutputs::CaseOutputs(std::string directory, std::string case_name)
    : directory_(std::move(directory)), case_name_(std::move(case_name)) {}

std::string CaseOutputs::netcdf() const {
  return (fs::path(directory_) / (case_name_ + ".nc")).string();
}

std::string CaseOutputs::partialNetcdf() const { return netcdf() + ".partial"; }

std::string CaseOutputs::vtk(int step) const {
  return (fs::path(directory_) / (case_name_ + "-" + std::to_string(step) + ".vtk")).string();
}

std::string CaseOutputs::summary() const {
  return (fs::path(directory_) / (case_name_ + ".summary.json")).string();
}

std::string CaseOutputs::figure() const {
  return (fs::path(directory_) / (case_name_ + ".png")).string();
}

std::string CaseOutputs::lock() const {
  return (fs::path(directory_) / ("." + case_name_ + ".lock")).string();
}

void CaseOutputs::removeStale(const std::set<int>& vtk_steps) const {
  for (const fs::directory_entry& entry : fs::directory_iterator(directory_)) {
    if (!entry.is_symlink() && !entry.is_regular_file()) continue;  // a directory is no output
    const std::string file = entry.path().filename().string();
    const std::optional<int> step = vtkStep(file, case_name_);
    if ((step && !vtk_steps.count(*step)) || isTemporary(file, case_name_))
      removeEntry(entry.path().string());
  }
}

}  // namespace flexmoor::app
