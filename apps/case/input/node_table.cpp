#include "apps/case/input/node_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <unordered_set>

namespace flexmoor::app {
namespace {

// A cursor over one line of text.
struct Cursor {
  const char* p;
  const char* end;
  void skipSpaces() {
    while (p < end && *p == ' ') ++p;
  }
  bool take(char c) {
    skipSpaces();
    if (p == end || *p != c) return false;
    ++p;
    return true;
  }
  // The rest is blank or a comment.
  bool atEnd() {
    skipSpaces();
    return p == end || *p == '#' || *p == '\r';
  }
  bool integer(int& value) {
    const auto [next, error] = std::from_chars(p, end, value);
    if (error != std::errc() || next == p) return false;
    p = next;
    return true;
  }
  // A plain number as parseValue reads one without a unit: an optional '+', finite.
  bool number(double& value) {
    skipSpaces();
    if (p < end && *p == '+') ++p;
    const auto [next, error] = std::from_chars(p, end, value);
    if (error != std::errc() || next == p || !std::isfinite(value)) return false;
    p = next;
    return true;
  }
};

// One entry `ID: [X, Y, Z]` of the table (after its indentation).
bool readEntry(Cursor c, int& id, Eigen::Vector3d& x) {
  if (!c.integer(id) || id < 1 || c.p == c.end || *c.p != ':' || ++c.p == c.end || *c.p != ' ')
    return false;
  if (!c.take('[')) return false;
  for (int k = 0; k < 3; ++k)
    if (!c.number(x(k)) || !c.take(k < 2 ? ',' : ']')) return false;
  return c.atEnd();
}

}  // namespace

std::optional<NodeTable> takeNodeTable(std::string& text) {
  // Find `nodes:` at the start of a line, alone on it (or with a comment).
  size_t start = 0;
  int line = 1;
  for (;;) {
    if (text.compare(start, 6, "nodes:") == 0) {
      Cursor rest{text.data() + start + 6, text.data() + text.find('\n', start)};
      if (text.find('\n', start) == std::string::npos) rest.end = text.data() + text.size();
      if (rest.atEnd()) break;
    }
    start = text.find('\n', start);
    if (start == std::string::npos) return std::nullopt;
    ++start;
    ++line;
  }
  NodeTable table;
  table.key_line = line;
  std::unordered_set<int> seen;
  size_t indent = 0;
  size_t p = text.find('\n', start);
  size_t blank_from = p;  // the table's text, from the end of the `nodes:` line
  while (p != std::string::npos) {
    const size_t first = p + 1;
    size_t last = text.find('\n', first);
    if (last == std::string::npos) last = text.size();
    ++line;
    Cursor c{text.data() + first, text.data() + last};
    c.skipSpaces();
    const size_t spaces = c.p - (text.data() + first);
    if (c.atEnd()) {  // blank or a comment
      p = last < text.size() ? last : std::string::npos;
      continue;
    }
    if (spaces == 0) break;  // the next top-level key
    if (indent == 0) indent = spaces;
    int id = 0;
    Eigen::Vector3d x;
    if (spaces != indent || !readEntry(c, id, x) || !seen.insert(id).second) return std::nullopt;
    table.ids.push_back(id);
    table.points.push_back(x);
    table.lines.push_back(line);
    blank_from = last;
    p = last < text.size() ? last : std::string::npos;
  }
  if (table.ids.empty()) return std::nullopt;
  // Blank the entries' lines, keeping their newlines (and so every later line's number).
  const size_t from = text.find('\n', start);
  for (size_t i = from; i < blank_from; ++i)
    if (text[i] != '\n') text[i] = ' ';
  return table;
}

bool tableFits(const YAML::Node& root, const NodeTable& table) {
  return root.IsMap() && std::any_of(root.begin(), root.end(), [&](const auto& kv) {
           return kv.first.IsScalar() && kv.first.Scalar() == "nodes" && kv.second.IsNull() &&
                  kv.first.Mark().line + 1 == table.key_line;
         });
}

}  // namespace flexmoor::app
