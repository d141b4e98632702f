#pragma once
// A fast path for the bulk of a large case file, its node table. yaml-cpp takes about 10 us and
// 2.5 kB a node of `nodes:` (a 1.8 M-node file: 20 s, 4.5 GB). When the top-level `nodes:` block
// has only lines `ID: [X, Y, Z]` of a whole-number id and three plain numbers (comments and
// blank lines aside), it is read here straight from the text and blanked out of the text that
// yaml-cpp then parses, so every other line keeps its number. Anything else in the block (a
// unit, an anchor, a flow map, a repeated id, a number that is not one) leaves the file to
// yaml-cpp whole, so that the reader's messages are the same either way.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace flexmoor::app {

struct NodeTable {
  int key_line = 0;                     // 1-based line of `nodes:`
  std::vector<int> ids;                 // in file order, each >= 1 and given once
  std::vector<Eigen::Vector3d> points;  // in the case's unit system (plain numbers)
  std::vector<int> lines;               // 1-based line of each
};

// Takes the node table out of `text` (its lines left empty) when the fast path applies.
std::optional<NodeTable> takeNodeTable(std::string& text);

// Whether yaml-cpp, parsing the text takeNodeTable left, agrees that the table was the value of
// the top-level key `nodes` (now null) on the table's line; if not, parse the original text.
bool tableFits(const YAML::Node& root, const NodeTable& table);

}  // namespace flexmoor::app
