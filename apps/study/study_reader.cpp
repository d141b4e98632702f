#include "apps/study/study_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "apps/case/case_reader.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/case/input/yaml_load.hpp"
#include "apps/common/format_number.hpp"
#include "apps/study/file_text.hpp"
#include "apps/study/member_case.hpp"
#include "apps/study/study_parameters.hpp"
#include "apps/study/value_path.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

// A name for netCDF and xarray: a letter, then letters, digits and '_'.
bool plainName(const std::string& name) {
  return !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])) &&
         std::all_of(name.begin(), name.end(), [](char ch) {
           return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
         });
}

// A path of grid: or list:, checked against the base case.
bool checkPath(Diagnostics& diag, const MapEntry& e, const std::string& where,
               const YAML::Node& base, const std::string& base_file) {
  std::string missing;
  if (nodeAtPath(base, e.key, missing)) return true;
  diag.error(e.key_node, where + ": not a value of the base case " + base_file + " (got '" + e.key +
                             "': " + missing + "; a study varies values the base case " + "gives)");
  return false;
}

// grid: PATH -> [values]: its paths and values (each list non-empty).
std::vector<std::vector<MemberValue>> readGrid(Diagnostics& diag, const YAML::Node& n,
                                               const YAML::Node& base,
                                               const std::string& base_file) {
  std::vector<std::vector<MemberValue>> axes;
  for (const MapEntry& e : mapEntries(diag, n, "grid")) {
    const std::string path = childPath("grid", e.key);
    if (!checkPath(diag, e, path, base, base_file)) continue;
    const std::vector<YAML::Node> items = listItems(diag, e.value, path);
    if (items.empty() && e.value.IsSequence())
      diag.error(e.value, path + ": no values (got an empty list, expected at least one)");
    if (items.empty()) continue;
    std::vector<MemberValue> axis;
    for (const YAML::Node& item : items) axis.push_back({e.key, item, lineOf(item)});
    axes.push_back(std::move(axis));
  }
  return axes;
}

// list: - {PATH: value}: the members' values and lines.
std::vector<std::pair<std::vector<MemberValue>, int>> readList(Diagnostics& diag,
                                                               const YAML::Node& n,
                                                               const YAML::Node& base,
                                                               const std::string& base_file) {
  std::vector<std::pair<std::vector<MemberValue>, int>> members;
  const std::vector<YAML::Node> items = listItems(diag, n, "list");
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string path = itemPath("list", i);
    std::vector<MemberValue> values;
    for (const MapEntry& e : mapEntries(diag, items[i], path))
      if (checkPath(diag, e, childPath(path, e.key), base, base_file))
        values.push_back({e.key, e.value, lineOf(e.value)});
    if (items[i].IsMap() && items[i].size() == 0)
      diag.error(items[i], path + ": no values (got an empty map, expected PATH: VALUE)");
    members.emplace_back(std::move(values), lineOf(items[i]));
  }
  return members;
}

// The outer product of the list's members (or one empty member) and the grid's axes.
std::vector<StudyMember> expand(const std::vector<std::pair<std::vector<MemberValue>, int>>& list,
                                const std::vector<std::vector<MemberValue>>& axes) {
  std::vector<std::pair<std::vector<MemberValue>, int>> rows =
      list.empty() ? std::vector<std::pair<std::vector<MemberValue>, int>>{{{}, 0}} : list;
  for (const std::vector<MemberValue>& axis : axes) {
    std::vector<std::pair<std::vector<MemberValue>, int>> next;
    for (const auto& row : rows)
      for (const MemberValue& v : axis) {
        auto values = row.first;
        values.push_back(v);
        next.emplace_back(std::move(values), row.second ? row.second : v.line);
      }
    rows = std::move(next);
  }
  std::vector<StudyMember> members;
  for (auto& [values, line] : rows)
    members.push_back({static_cast<int>(members.size()) + 1, std::move(values), line, ""});
  return members;
}

std::vector<Statistic> readStatistics(Input& in, const YAML::Node* n, const std::string& path) {
  if (!n)
    return {Statistic::Max, Statistic::Min, Statistic::Mean, Statistic::Std, Statistic::Amplitude};
  std::vector<Statistic> stats;
  const std::vector<YAML::Node> items = listOrOne(in.diag, *n, path);
  for (size_t i = 0; i < items.size(); ++i) {
    const auto s = in.choice<Statistic>(items[i], listOrOnePath(*n, path, i),
                                        {{"max", Statistic::Max},
                                         {"min", Statistic::Min},
                                         {"mean", Statistic::Mean},
                                         {"std", Statistic::Std},
                                         {"amplitude", Statistic::Amplitude},
                                         {"mpm", Statistic::Mpm}});
    if (!s) continue;
    if (std::find(stats.begin(), stats.end(), *s) != stats.end())
      in.diag.error(items[i], listOrOnePath(*n, path, i) + ": given twice (got '" +
                                  items[i].Scalar() + "' again, expected each statistic once)");
    else
      stats.push_back(*s);
  }
  return stats;
}

std::optional<MpmSpec> readMpm(Input& in, const YAML::Node& n, const std::string& path) {
  Fields f(in.diag, n, path, {"duration", "fit"});
  const YAML::Node* d = f.require("duration");
  const YAML::Node* fit = f.require("fit");
  const auto duration =
      d ? in.quantity(*d, f.path("duration"), kind::kTime, Limit::Positive) : std::nullopt;
  const auto which =
      fit ? in.choice<MpmFit>(*fit, f.path("fit"),
                              {{"weibull", MpmFit::Weibull}, {"gumbel", MpmFit::Gumbel}})
          : std::nullopt;
  if (!duration || !which) return std::nullopt;
  return MpmSpec{*duration, *which};
}

// One collect: entry's own keys; the quantity's are read against each member's case.
std::optional<CollectSpec> readCollect(Input& in, const YAML::Node& n, const std::string& path,
                                       std::set<std::string>& names) {
  if (!n.IsMap()) {
    in.diag.error(
        n, path + ": not a map (got " + describeNode(n) + ", expected {name, quantity, ...})");
    return std::nullopt;
  }
  CollectSpec spec;
  spec.path = path;
  spec.line = lineOf(n);
  spec.map = n;
  bool ok = true;
  const YAML::Node name = n["name"];
  if (!name) {
    in.diag.error(n, path + ": missing key 'name'");
    ok = false;
  } else if (const auto text = in.text(name, childPath(path, "name"))) {
    spec.name = *text;
    if (!plainName(spec.name)) {
      in.diag.error(name, childPath(path, "name") + ": not usable as a variable name (got '" +
                              spec.name + "', expected a letter, then letters, digits and '_')");
      ok = false;
    } else if (!names.insert(spec.name).second) {
      in.diag.error(name, childPath(path, "name") + ": given to another entry (got '" + spec.name +
                              "' again, expected a name of its own)");
      ok = false;
    }
  } else {
    ok = false;
  }
  const YAML::Node statistics = n["statistics"];
  spec.statistics =
      readStatistics(in, statistics ? &statistics : nullptr, childPath(path, "statistics"));
  const bool wants_mpm = std::find(spec.statistics.begin(), spec.statistics.end(),
                                   Statistic::Mpm) != spec.statistics.end();
  const YAML::Node mpm = n["mpm"];
  if (wants_mpm && !mpm) {
    in.diag.error(n, path + ": mpm among the statistics without mpm: (expected mpm: {duration, " +
                         "fit: weibull | gumbel})");
    ok = false;
  } else if (mpm && !wants_mpm) {
    in.diag.error(mpm, childPath(path, "mpm") + ": not used without mpm among the statistics " +
                           "(expected statistics: [..., mpm])");
    ok = false;
  } else if (mpm) {
    spec.mpm = readMpm(in, mpm, childPath(path, "mpm"));
    ok = ok && spec.mpm;
  }
  if (const YAML::Node spectrum = n["spectrum"]) {
    Fields f(in.diag, spectrum, childPath(path, "spectrum"), {"segment"});
    const YAML::Node* segment = f.require("segment");
    spec.segment = segment ? in.quantity(*segment, f.path("segment"), kind::kTime, Limit::Positive)
                           : std::nullopt;
    ok = ok && spec.segment;
  }
  if (!ok) return std::nullopt;
  return spec;
}

// case: the base case, relative to the study file, loaded (its values set per member later).
std::optional<CaseDocument> readBaseCase(Input& in, const YAML::Node& n,
                                         const std::string& study_file, Study& study) {
  const auto name = in.text(n, "case");
  if (!name) return std::nullopt;
  const fs::path file = fs::path(study_file).parent_path() / *name;
  study.base_case = file.lexically_normal().string();
  if (!fs::is_regular_file(file)) {
    in.diag.error(n, "case: no such file (got '" + *name + "', " + study.base_case +
                         ", expected the base case's file, relative to the study)");
    return std::nullopt;
  }
  try {
    return loadCase(study.base_case);
  } catch (const CaseError& e) {
    for (const std::string& m : e.messages())
      in.diag.error(n, "case: the base case is not valid YAML: " + m);
  }
  return std::nullopt;
}

std::vector<CollectSpec> readCollectList(Input& in, const YAML::Node& n) {
  std::vector<CollectSpec> collect;
  std::set<std::string> names;
  const std::vector<YAML::Node> items = listItems(in.diag, n, "collect");
  if (items.empty() && n.IsSequence())
    in.diag.error(n,
                  "collect: nothing to collect (got an empty list, expected at least one "
                  "entry)");
  for (size_t i = 0; i < items.size(); ++i)
    if (auto spec = readCollect(in, items[i], itemPath("collect", i), names))
      collect.push_back(std::move(*spec));
  return collect;
}

// Every spectrum of one segment: study.nc has one frequency axis.
void checkSpectrumSegments(Diagnostics& diag, const std::vector<CollectSpec>& collect) {
  const CollectSpec* first = nullptr;
  for (const CollectSpec& c : collect) {
    if (!c.segment) continue;
    if (!first)
      first = &c;
    else if (*c.segment != *first->segment)
      diag.error(c.line, c.path + ".spectrum.segment: not the segment of " + first->path +
                             " (got " + formatNumber(*c.segment) + " s, expected " +
                             formatNumber(*first->segment) +
                             " s: study.nc has one frequency axis)");
  }
}

// Every member's case built and checked; the collect: entries' problems reported for the first
// member they are found in only.
void checkMembers(Diagnostics& diag, Study& study, std::string& case_name, UnitSystem& units) {
  bool collect_reported = false;
  for (const StudyMember& m : study.members) {
    Diagnostics collect_diag(study.file);
    const auto member = buildMember(study, m, diag, collect_diag);
    if (!collect_diag.empty() && !collect_reported) {  // again, to report them
      Diagnostics case_diag(study.file);
      buildMember(study, m, case_diag, diag);
      collect_reported = true;
    }
    if (!member) continue;
    case_name = member->c.name;
    units = member->c.units;
    for (size_t k = 0; k < member->collect.size() && k < study.collect.size(); ++k)
      study.collect[k].units = member->collect[k].unit;
    const auto stepOf = [&member](const SummarySpec& s) {
      return s.step < 0 ? static_cast<int>(member->c.steps.size()) - 1 : s.step;
    };
    for (size_t k = 1; k < member->collect.size() && !collect_reported; ++k) {
      const int step = stepOf(member->collect.front()), other = stepOf(member->collect[k]);
      if (other == step) continue;
      diag.error(study.collect[k].line, study.collect[k].path + ": a series of another step than " +
                                            study.collect.front().path + "'s (got step '" +
                                            member->c.steps[other].name + "', expected step '" +
                                            member->c.steps[step].name +
                                            "': series.nc has one time axis)");
      collect_reported = true;
    }
  }
}

}  // namespace

Study readStudy(const std::string& path) {
  Diagnostics diag(path);
  std::optional<NodeTable> no_table;
  const YAML::Node root = loadCaseDocument(diag, no_table);
  Fields top(diag, root, "", {"title", "case", "grid", "list", "collect"});
  Input in(diag, UnitSystem::SI);
  Study study;
  study.file = path;
  if (const YAML::Node* t = top.find("title")) study.title = in.text(*t, "title").value_or("");
  const YAML::Node* case_node = top.require("case");
  const YAML::Node* collect_node = top.require("collect");
  const YAML::Node* grid = top.find("grid");
  const YAML::Node* list = top.find("list");
  if (!grid && !list && top.isMap()) diag.error(root, "no members (expected grid:, list: or both)");
  const std::optional<CaseDocument> base =
      case_node ? readBaseCase(in, *case_node, path, study) : std::nullopt;
  if (collect_node) study.collect = readCollectList(in, *collect_node);
  checkSpectrumSegments(diag, study.collect);
  if (base) {
    const YAML::Node none;
    const auto axes = readGrid(diag, grid ? *grid : none, base->root, study.base_case);
    const auto members = readList(diag, list ? *list : none, base->root, study.base_case);
    if (diag.empty()) study.members = expand(members, axes);
  }
  diag.throwIfAny();
  std::string case_name;
  UnitSystem units = UnitSystem::SI;
  const QuantityMarks marks;  // the dimensions the members' cases read their values as
  checkMembers(diag, study, case_name, units);
  diag.throwIfAny();
  study.case_name = case_name;
  study.unit_system = unitSystemName(units);
  const std::string base_text = fileText(study.base_case);
  for (StudyMember& m : study.members) m.hash = memberHash(base_text, m, study.collect);
  study.parameters = studyParameters(study.members, base->root, marks, units);
  return study;
}

bool isStudyFile(const std::string& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path);
    return root.IsMap() && root["case"] && root["collect"];
  } catch (const YAML::Exception&) {
    return false;
  }
}

}  // namespace flexmoor::app
