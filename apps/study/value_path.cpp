#include "apps/study/value_path.hpp"

#include <charconv>
#include <vector>

namespace flexmoor::app {
namespace {

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> keys;
  size_t start = 0;
  while (true) {
    const size_t dot = path.find('.', start);
    keys.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return keys;
    start = dot + 1;
  }
}

std::string where(const std::vector<std::string>& keys, size_t k) {
  std::string w;
  for (size_t i = 0; i < k; ++i) w += (i ? "." : "") + keys[i];
  return w.empty() ? "the case's top level" : w;
}

// The node at keys[k..] below `node` (a handle into the document: never assigned over).
std::optional<YAML::Node> descend(YAML::Node node, const std::vector<std::string>& keys, size_t k,
                                  std::string& missing) {
  if (k == keys.size()) return node;
  const std::string& key = keys[k];
  if (node.IsMap()) {
    std::string present;
    for (auto kv : node) {
      if (!kv.first.IsScalar()) continue;
      if (kv.first.Scalar() == key) return descend(kv.second, keys, k + 1, missing);
      present += (present.empty() ? "" : ", ") + kv.first.Scalar();
    }
    missing = "no key '" + key + "' in " + where(keys, k) + " (expected one of: " + present + ")";
    return std::nullopt;
  }
  if (node.IsSequence()) {
    size_t index = 0;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
    if (ec != std::errc() || end != key.data() + key.size() || index >= node.size()) {
      missing = "no item '" + key + "' in the list " + where(keys, k) +
                " (expected an index 0 to " + std::to_string(node.size() - 1) + ")";
      return std::nullopt;
    }
    return descend(node[index], keys, k + 1, missing);
  }
  missing = where(keys, k) + " holds no '" + key + "' (got a single value, expected a map or list)";
  return std::nullopt;
}

}  // namespace

std::optional<YAML::Node> nodeAtPath(const YAML::Node& root, const std::string& path,
                                     std::string& missing) {
  const std::vector<std::string> keys = splitPath(path);
  for (const std::string& key : keys)
    if (key.empty()) {
      missing = "an empty key in the path (expected keys joined by '.')";
      return std::nullopt;
    }
  return descend(root, keys, 0, missing);
}

void setNode(YAML::Node target, const YAML::Node& value) {
  if (value.IsScalar())
    target = value.Scalar();  // the node's data changed in place: its mark stays
  else
    target = YAML::Clone(value);
}

std::string pathVariableName(const std::string& path) {
  std::string name = path;
  for (char& ch : name)
    if (ch == '.') ch = '_';
  return name;
}

}  // namespace flexmoor::app
