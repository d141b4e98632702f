#include "apps/study/member_case.hpp"

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>

#include "apps/study/value_path.hpp"

namespace flexmoor::app {
namespace {

// The document with the member's values set; `value_lines` maps the line of each value in the
// base case to the line of the study's value that replaced it. Nullopt after reporting a path
// the base case does not have.
std::optional<CaseDocument> memberDocument(const Study& study, const StudyMember& member,
                                           std::map<int, int>& value_lines, Diagnostics& diag) {
  CaseDocument document = loadCase(study.base_case);
  for (const MemberValue& v : member.values) {
    std::string missing;
    const auto target = nodeAtPath(document.root, v.path, missing);
    if (!target) {
      diag.error(v.line, "member " + std::to_string(member.index) + ": " + v.path + ": " + missing);
      return std::nullopt;
    }
    value_lines[lineOf(*target)] = v.line;
    setNode(*target, v.value);
  }
  return document;
}

// The line a case message names ("FILE:LINE: ..."), or 0.
int messageLine(const std::string& message, const std::string& file) {
  if (message.rfind(file + ":", 0) != 0) return 0;
  int line = 0;
  if (std::sscanf(message.c_str() + file.size() + 1, "%d", &line) != 1) return 0;
  return line;
}

void addHash(uint64_t& h, const std::string& text) {
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ull;  // FNV-1a's 64-bit prime
  }
  h ^= 0xff;  // a separator, so that "ab" + "c" and "a" + "bc" differ
  h *= 1099511628211ull;
}

}  // namespace

std::string describeValues(const StudyMember& member) {
  std::string text;
  for (const MemberValue& v : member.values)
    text += (text.empty() ? "" : ", ") + v.path + " = " +
            (v.value.IsScalar() ? v.value.Scalar() : YAML::Dump(v.value));
  return text;
}

std::optional<MemberCase> buildMember(const Study& study, const StudyMember& member,
                                      Diagnostics& diag, Diagnostics& collect_diag) {
  std::map<int, int> value_lines;
  const auto document = memberDocument(study, member, value_lines, diag);
  if (!document) return std::nullopt;
  ForeignSeries series;
  series.diag = &collect_diag;
  series.prefix = "member " + std::to_string(member.index) + ": ";
  for (const CollectSpec& spec : study.collect)
    series.entries.push_back(
        {spec.map, spec.path, spec.name, {"name", "statistics", "mpm", "spectrum"}});
  try {
    MemberCase out{readCase(*document, &series), {}};
    for (const std::string& w : out.c.warnings) std::cerr << "flexmoor: " << w << "\n";
    for (const auto& spec : series.specs) {
      if (!spec) return std::nullopt;  // reported to collect_diag
      out.collect.push_back(*spec);
    }
    return out;
  } catch (const CaseError& e) {
    const std::string intro = "member " + std::to_string(member.index) + " (" +
                              describeValues(member) + "): the member's case is not valid: ";
    for (const std::string& message : e.messages()) {
      const auto it = value_lines.find(messageLine(message, document->path));
      diag.error(it == value_lines.end() ? member.line : it->second, intro + message);
    }
    return std::nullopt;
  }
}

MemberCase buildMember(const Study& study, const StudyMember& member) {
  Diagnostics diag(study.file);
  auto out = buildMember(study, member, diag, diag);
  diag.throwIfAny();
  if (!out)
    throw CaseError({study.file + ": member " + std::to_string(member.index) +
                     ": its case could not be built"});
  return std::move(*out);
}

std::string memberHash(const std::string& base_text, const StudyMember& member,
                       const std::vector<CollectSpec>& collect) {
  uint64_t h = 14695981039346656037ull;  // FNV-1a's 64-bit offset basis
  addHash(h, base_text);
  for (const MemberValue& v : member.values) {
    addHash(h, v.path);
    addHash(h, YAML::Dump(v.value));
  }
  for (const CollectSpec& spec : collect) addHash(h, YAML::Dump(spec.map));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace flexmoor::app
