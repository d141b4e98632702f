#include "apps/study/member_store.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "apps/output/atomic_output.hpp"
#include "apps/study/file_text.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& text) {
  const size_t a = text.find_first_not_of(" \n\t\r");
  if (a == std::string::npos) return "";
  return text.substr(a, text.find_last_not_of(" \n\t\r") - a + 1);
}

}  // namespace

std::string memberDirectory(const std::string& dir, int index) {
  char name[16];
  std::snprintf(name, sizeof name, "%04d", index);
  return (fs::path(dir) / "members" / name).string();
}

std::string seriesPath(const std::string& dir, int index) {
  return (fs::path(memberDirectory(dir, index)) / "series.nc").string();
}

bool isComplete(const std::string& dir, const StudyMember& member) {
  const fs::path marker = fs::path(memberDirectory(dir, member.index)) / "complete";
  return fs::is_regular_file(marker) && trim(fileText(marker.string())) == member.hash &&
         fs::is_regular_file(seriesPath(dir, member.index));
}

void markComplete(const std::string& dir, const StudyMember& member) {
  writeFileAtomically((fs::path(memberDirectory(dir, member.index)) / "complete").string(),
                      member.hash + "\n");
}

void markFailed(const std::string& dir, const StudyMember& member, int status,
                const std::string& error) {
  fs::create_directories(memberDirectory(dir, member.index));
  writeFileAtomically((fs::path(memberDirectory(dir, member.index)) / "failed").string(),
                      std::to_string(status) + "\n" + error + "\n");
}

void clearOutcome(const std::string& dir, const StudyMember& member) {
  std::error_code ec;
  fs::remove(fs::path(memberDirectory(dir, member.index)) / "complete", ec);
  fs::remove(fs::path(memberDirectory(dir, member.index)) / "failed", ec);
}

MemberOutcome readOutcome(const std::string& dir, const StudyMember& member) {
  if (isComplete(dir, member)) return {kComplete, ""};
  const fs::path failed = fs::path(memberDirectory(dir, member.index)) / "failed";
  if (!fs::is_regular_file(failed)) return {kFailed, "did not run (no outcome recorded)"};
  // The status on the first line, the error after it.
  const std::string text = fileText(failed.string());
  const size_t end = std::min(text.find('\n'), text.size());
  int status = std::atoi(text.substr(0, end).c_str());
  if (status != kStatusBadInput && status != kStatusNotConverged) status = kFailed;
  return {status, trim(text.substr(end))};
}

std::string fileTail(const std::string& path, size_t bytes) {
  const std::string text = trim(fileText(path));
  return text.size() <= bytes ? text : "..." + text.substr(text.size() - bytes);
}

}  // namespace flexmoor::app
