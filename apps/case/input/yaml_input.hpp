#pragma once
// Checked access to the values of a YAML case file. Each reader reports what is wrong to the
// Diagnostics, with the value's line and its path in the file ("materials.steel.E"), and returns
// std::nullopt so that the caller carries on and the file's other problems are found too.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <climits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/units.hpp"

namespace flexmoor::app {

// "steps[2].static" + "increments" -> "steps[2].static.increments"; list items are 1-based.
std::string childPath(const std::string& path, const std::string& key);
std::string itemPath(const std::string& path, size_t index);

// What a node holds, for "(got ...)": 'text', a list, a map or nothing.
std::string describeNode(const YAML::Node& n);

// One entry of a YAML map, with its key's node for the key's line.
//
// Never assign one YAML::Node over another: yaml-cpp's assignment does not rebind the handle but
// makes the node it refers to, in the document itself, an alias of the other. A list of nodes may
// be built (push_back) and read, but not erased from, sorted or swapped. MapEntry cannot be
// assigned, so that std::remove_if and the like do not compile on its lists.
struct MapEntry {
  std::string key;
  YAML::Node key_node;
  YAML::Node value;

  MapEntry& operator=(const MapEntry&) = delete;
};

// The entries of a map in file order; a null value counts as an empty map. Reports a value that
// is not a map, keys that are not scalars, and repeated keys (their first occurrence is kept).
std::vector<MapEntry> mapEntries(Diagnostics& diag, const YAML::Node& map, const std::string& path);

// The items of a list; a null value counts as an empty list. Reports a value that is not a list.
std::vector<YAML::Node> listItems(Diagnostics& diag, const YAML::Node& list,
                                  const std::string& path);

// A list's items, or a single value as a list of one (`on: roof` or `on: [roof, walls]`).
std::vector<YAML::Node> listOrOne(Diagnostics& diag, const YAML::Node& n, const std::string& path);

// The path of item i of what listOrOne read: "path[i]" for a list, "path" for a single value.
std::string listOrOnePath(const YAML::Node& n, const std::string& path, size_t i);

// The text of `key` in a map, or "" (to choose which keys apply before checking them).
std::string peekText(const YAML::Node& map, const char* key);

// A map with a fixed set of keys. Unknown keys are reported on construction, with the allowed
// keys and the nearest one ("did you mean 'elements'?").
class Fields {
 public:
  Fields(Diagnostics& diag, const YAML::Node& map, std::string path,
         std::vector<std::string> allowed);

  const YAML::Node* find(const std::string& key) const;  // nullptr when absent
  const YAML::Node* require(const std::string& key);     // reports a missing key in a map
  int keyLine(const std::string& key) const;             // 1-based line of a present key, else 0
  std::string path(const std::string& key) const { return childPath(path_, key); }
  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return map_; }
  bool isMap() const { return is_map_; }

 private:
  Diagnostics& diag_;
  YAML::Node map_;
  std::string path_;
  std::vector<MapEntry> entries_;
  bool is_map_;  // a map or null; else already reported, and its keys are not asked for again
};

enum class Limit { Any, Positive, NonNegative };

// The largest magnitude, in SI units, of any value Input::quantity accepts (beyond it a value is
// refused as no physical input: the solver's products of it would overflow). The values whose
// size physics bounds more closely are checked against their own ranges (physical_range.hpp).
inline constexpr double kLargestMagnitude = 1e30;

// The dimension of every quantity Input::quantity reads on this thread while a QuantityMarks is
// alive, by the place of its value in the file (YAML::Mark's line and column): a study's
// parameters take the units of the values they vary from it (apps/study/study_parameters.hpp).
// Marks of one file only: a value set from another file keeps its own place.
class QuantityMarks {
 public:
  QuantityMarks();  // records until destroyed (the one before it resumes then)
  ~QuantityMarks();
  QuantityMarks(const QuantityMarks&) = delete;
  QuantityMarks& operator=(const QuantityMarks&) = delete;

  // The dimension the value at `n`'s place was read as; nullopt for a value not read as one.
  std::optional<Dimension> at(const YAML::Node& n) const;
  // Where Input::quantity tells it what it read (nothing when none is recording).
  static void note(const YAML::Node& n, const Dimension& d);

 private:
  std::map<std::pair<int, int>, Dimension> marks_;
  QuantityMarks* previous_ = nullptr;
};

// Scalar readers in one unit system.
class Input {
 public:
  Input(Diagnostics& diag, UnitSystem units) : diag(diag), units(units) {}

  // A number, or "NUMBER UNIT" of the right dimension, converted to the case's system: finite,
  // of magnitude at most kLargestMagnitude in SI, and within `limit`.
  std::optional<double> quantity(const YAML::Node& n, const std::string& path,
                                 const QuantityKind& kind, Limit limit = Limit::Any);
  // A whole number in [min, max].
  std::optional<int> integer(const YAML::Node& n, const std::string& path, int min,
                             int max = INT_MAX);
  // A scalar's text.
  std::optional<std::string> text(const YAML::Node& n, const std::string& path);
  // [x, y, z], each a quantity of `kind`.
  std::optional<Eigen::Vector3d> vector3(const YAML::Node& n, const std::string& path,
                                         const QuantityKind& kind);
  // One of a fixed set of words.
  template <class T>
  std::optional<T> choice(const YAML::Node& n, const std::string& path,
                          const std::vector<std::pair<std::string, T>>& options);

  // Optional field helpers: the default when the key is absent.
  double quantityOr(const Fields& f, const std::string& key, const QuantityKind& kind, Limit limit,
                    double fallback);
  int integerOr(const Fields& f, const std::string& key, int min, int fallback);

  Diagnostics& diag;
  UnitSystem units;

 private:
  void reportChoice(const YAML::Node& n, const std::string& path,
                    const std::vector<std::string>& words);
};

template <class T>
std::optional<T> Input::choice(const YAML::Node& n, const std::string& path,
                               const std::vector<std::pair<std::string, T>>& options) {
  const std::optional<std::string> word = text(n, path);
  if (!word) return std::nullopt;
  for (const auto& [name, value] : options)
    if (*word == name) return value;
  std::vector<std::string> words;
  for (const auto& option : options) words.push_back(option.first);
  reportChoice(n, path, words);
  return std::nullopt;
}

}  // namespace flexmoor::app
