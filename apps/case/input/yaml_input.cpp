#include "apps/case/input/yaml_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <unordered_map>

#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "; did you mean 'elements'?" when one allowed word is within a third of the word's length.
std::string suggestion(const std::string& word, const std::vector<std::string>& allowed) {
  const std::string* best = nullptr;
  size_t best_distance = std::max<size_t>(1, word.size() / 3) + 1;
  for (const std::string& a : allowed) {
    const size_t d = editDistance(word, a);
    if (d < best_distance) best = &a, best_distance = d;
  }
  return best ? "; did you mean '" + *best + "'?" : "";
}

std::string prefix(const std::string& path) { return path.empty() ? "" : path + ": "; }

}  // namespace

std::string describeNode(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar:
      return "'" + n.Scalar() + "'";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "nothing";
  }
}

std::string childPath(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string itemPath(const std::string& path, size_t index) {
  return path + "[" + std::to_string(index + 1) + "]";
}

std::vector<MapEntry> mapEntries(Diagnostics& diag, const YAML::Node& map,
                                 const std::string& path) {
  std::vector<MapEntry> entries;
  if (map.IsNull()) return entries;
  if (!map.IsMap()) {
    diag.error(map,
               prefix(path) + "expected a map of 'key: value' (got " + describeNode(map) + ")");
    return entries;
  }
  std::unordered_map<std::string, size_t> index;  // key -> its entry
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) {
      diag.error(kv.first,
                 prefix(path) + "a key must be a word (got " + describeNode(kv.first) + ")");
      continue;
    }
    const std::string& key = kv.first.Scalar();
    // A hash of the keys so far: a map of a million nodes is read in linear time.
    const auto [first, added] = index.emplace(key, entries.size());
    if (!added) {
      diag.error(kv.first, childPath(path, key) + ": repeated key (first given on line " +
                               std::to_string(lineOf(entries[first->second].key_node)) + ")");
      continue;
    }
    entries.push_back({key, kv.first, kv.second});
  }
  return entries;
}

std::vector<YAML::Node> listItems(Diagnostics& diag, const YAML::Node& list,
                                  const std::string& path) {
  std::vector<YAML::Node> items;
  if (list.IsNull()) return items;
  if (!list.IsSequence()) {
    diag.error(list, prefix(path) + "expected a list (got " + describeNode(list) + ")");
    return items;
  }
  for (const YAML::Node& item : list) items.push_back(item);
  return items;
}

std::vector<YAML::Node> listOrOne(Diagnostics& diag, const YAML::Node& n, const std::string& path) {
  if (n.IsSequence()) return listItems(diag, n, path);
  return {n};
}

std::string listOrOnePath(const YAML::Node& n, const std::string& path, size_t i) {
  return n.IsSequence() ? itemPath(path, i) : path;
}

std::string peekText(const YAML::Node& map, const char* key) {
  if (!map.IsMap()) return "";
  const YAML::Node value = map[key];  // invalid (not merely null) when the key is absent
  return value.IsDefined() && value.IsScalar() ? value.Scalar() : "";
}

Fields::Fields(Diagnostics& diag, const YAML::Node& map, std::string path,
               std::vector<std::string> allowed)
    : diag_(diag), map_(map), path_(std::move(path)), is_map_(map.IsMap() || map.IsNull()) {
  // Kept entries are copied into a new list: erasing from a list of nodes would assign one
  // YAML::Node over another, which rebinds the node in the document itself (MapEntry forbids it).
  for (const MapEntry& e : mapEntries(diag, map, path_)) {
    if (std::find(allowed.begin(), allowed.end(), e.key) != allowed.end())
      entries_.push_back(e);
    else
      diag_.error(e.key_node, prefix(path_) + "unknown key '" + e.key + "' (expected one of: " +
                                  joined(allowed) + suggestion(e.key, allowed) + ")");
  }
}

const YAML::Node* Fields::find(const std::string& key) const {
  for (const MapEntry& e : entries_)
    if (e.key == key) return &e.value;
  return nullptr;
}

int Fields::keyLine(const std::string& key) const {
  for (const MapEntry& e : entries_)
    if (e.key == key) return lineOf(e.key_node);
  return 0;
}

const YAML::Node* Fields::require(const std::string& key) {
  const YAML::Node* n = find(key);
  if (!n && is_map_) diag_.error(map_, prefix(path_) + "missing key '" + key + "'");
  return n;
}

namespace {
thread_local QuantityMarks* recording = nullptr;
}  // namespace

QuantityMarks::QuantityMarks() : previous_(recording) { recording = this; }
QuantityMarks::~QuantityMarks() { recording = previous_; }

std::optional<Dimension> QuantityMarks::at(const YAML::Node& n) const {
  const auto found = marks_.find({n.Mark().line, n.Mark().column});
  if (found == marks_.end()) return std::nullopt;
  return found->second;
}

void QuantityMarks::note(const YAML::Node& n, const Dimension& d) {
  if (recording && n.Mark().line >= 0) recording->marks_[{n.Mark().line, n.Mark().column}] = d;
}

std::optional<double> Input::quantity(const YAML::Node& n, const std::string& path,
                                      const QuantityKind& kind, Limit limit) {
  if (!n.IsScalar()) {
    diag.error(n, path + ": expected " + kind.name + " (got " + describeNode(n) + ")");
    return std::nullopt;
  }
  QuantityMarks::note(n, kind.dimension);
  double value = 0.0;
  try {
    value = parseValue(n.Scalar(), kind, units);
  } catch (const UnitError& e) {
    diag.error(n, path + ": " + e.what());
    return std::nullopt;
  }
  // Finite in the case's units, and within kLargestMagnitude in SI: no physical input comes near
  // it, and the products the solver forms of such values overflow (1e308 ft/s^2 of gravity ends
  // a run in NaN).
  if (!std::isfinite(value)) {
    diag.error(n, path + ": out of range (got " + n.Scalar() +
                      ", not a finite number in the case's units, expected a finite value)");
    return std::nullopt;
  }
  if (!(std::abs(value * systemScale(kind.dimension, units)) <= kLargestMagnitude)) {
    diag.error(n, path + ": out of range (got " + n.Scalar() + ", expected a magnitude at most " +
                      formatNumber(kLargestMagnitude) +
                      " in SI units: no physical input comes near it)");
    return std::nullopt;
  }
  const bool below = (limit == Limit::Positive && !(value > 0.0)) ||
                     (limit == Limit::NonNegative && !(value >= 0.0));
  if (below) {
    diag.error(n, path + ": out of range (got " + n.Scalar() + ", expected " +
                      (limit == Limit::Positive ? "> 0" : ">= 0") + ")");
    return std::nullopt;
  }
  return value;
}

std::optional<int> Input::integer(const YAML::Node& n, const std::string& path, int min, int max) {
  const std::string range = max == INT_MAX ? ">= " + std::to_string(min)
                                           : std::to_string(min) + " to " + std::to_string(max);
  int value = 0;
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (error == std::errc() && end == s.data() + s.size()) {
      if (value >= min && value <= max) return value;
      diag.error(n, path + ": out of range (got " + s + ", expected " + range + ")");
      return std::nullopt;
    }
  }
  diag.error(n, path + ": expected a whole number " + range + " (got " + describeNode(n) + ")");
  return std::nullopt;
}

std::optional<std::string> Input::text(const YAML::Node& n, const std::string& path) {
  if (n.IsScalar() && !n.Scalar().empty()) return n.Scalar();
  diag.error(n, path + ": expected a word (got " + describeNode(n) + ")");
  return std::nullopt;
}

std::optional<Eigen::Vector3d> Input::vector3(const YAML::Node& n, const std::string& path,
                                              const QuantityKind& kind) {
  if (!n.IsSequence() || n.size() != 3) {
    const std::string got =
        n.IsSequence() ? "a list of " + std::to_string(n.size()) : describeNode(n);
    diag.error(n, path + ": expected [x, y, z], each " + kind.name + " (got " + got + ")");
    return std::nullopt;
  }
  Eigen::Vector3d v;
  bool ok = true;
  const char* axis[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const std::optional<double> c = quantity(n[k], childPath(path, axis[k]), kind);
    ok = ok && c.has_value();
    if (c) v(k) = *c;
  }
  return ok ? std::optional<Eigen::Vector3d>(v) : std::nullopt;
}

double Input::quantityOr(const Fields& f, const std::string& key, const QuantityKind& kind,
                         Limit limit, double fallback) {
  const YAML::Node* n = f.find(key);
  if (!n) return fallback;
  return quantity(*n, f.path(key), kind, limit).value_or(fallback);
}

int Input::integerOr(const Fields& f, const std::string& key, int min, int fallback) {
  const YAML::Node* n = f.find(key);
  if (!n) return fallback;
  return integer(*n, f.path(key), min).value_or(fallback);
}

void Input::reportChoice(const YAML::Node& n, const std::string& path,
                         const std::vector<std::string>& words) {
  diag.error(n, path + ": unknown value (got " + describeNode(n) +
                    ", expected one of: " + joined(words) + suggestion(n.Scalar(), words) + ")");
}

}  // namespace flexmoor::app
