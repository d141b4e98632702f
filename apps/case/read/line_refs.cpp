// Places on a named line, for what a case reports (summary: entries, figure: series, a study's
// collect: entries):
//   line: NAME, end: start | end | first | last | 1 | 2      the line's first or last node
//                    anchor | fairlead                        of a mooring line (anchor:)
//   line: NAME, node: K                                       its K-th node (1-based)
//   line: NAME, element: K, end: first | last | 1 | 2         its K-th element's end
// and for an element's end without line:, `element: ID, end: first | last | 1 | 2`.
#include <charconv>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

std::string lineNames(const CaseBuilder& b) {
  std::string names;
  for (const CaseLine& l : b.c.named_lines) names += (names.empty() ? "" : ", ") + l.name;
  return names.empty() ? "none defined" : names;
}

bool isMooring(const CaseLine& line) { return line.anchor != CaseLine::Anchor::None; }

std::string lineEndWords(const CaseLine& line) {
  return isMooring(line) ? "anchor, fairlead, start, end, first, last, 1 or 2"
                         : "start, end, first, last, 1 or 2";
}

// K of `node: K` or `element: K` of a line with `count` of them.
std::optional<int> ordinal(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                           const CaseLine& line, size_t count, const char* what) {
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  int k = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), k);
  if (error == std::errc() && end == s.data() + s.size() && k >= 1 && k <= static_cast<int>(count))
    return k - 1;
  b.diag.error(n, path + ": no such " + what + " of line '" + line.name + "' (got " +
                      describeNode(n) + ", expected 1 to " + std::to_string(count) + ", its " +
                      what + "s from its start)");
  return std::nullopt;
}

}  // namespace

const CaseLine* lineRef(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  const auto name = b.in.text(n, path);
  if (!name) return nullptr;
  for (const CaseLine& line : b.c.named_lines)
    if (line.name == *name) return &line;
  if (!b.broken_node_names.count(*name))
    b.diag.error(n, path + ": no line '" + *name + "' (got '" + *name +
                        "', expected one of the case's lines: " + lineNames(b) + ")");
  return nullptr;
}

std::optional<bool> lineEnd(CaseBuilder& b, const CaseLine& line, const YAML::Node& n,
                            const std::string& path) {
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  if (s == "start" || s == "first" || s == "1") return false;
  if (s == "end" || s == "last" || s == "2") return true;
  if (isMooring(line) && (s == "anchor" || s == "fairlead"))
    return (line.anchor == CaseLine::Anchor::End) == (s == "anchor");
  const bool mooring_word = s == "anchor" || s == "fairlead";
  b.diag.error(n, path + ": " +
                      (mooring_word ? "line '" + line.name + "' has no " + s
                                    : "not an end of line '" + line.name + "'") +
                      " (got " + describeNode(n) + ", expected " + lineEndWords(line) +
                      (mooring_word ? "; anchor and fairlead name the ends of a mooring line, a "
                                      "line with anchor: start | end)"
                                    : ")"));
  return std::nullopt;
}

std::optional<int> elementEnd(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  if (s == "first" || s == "1") return 0;
  if (s == "last" || s == "2") return 1;
  b.diag.error(n, path + ": not an end of an element (got " + describeNode(n) +
                      ", expected first or 1 for its first node, last or 2 for its last)");
  return std::nullopt;
}

std::optional<int> nodeOfEntry(CaseBuilder& b, Fields& f) {
  const YAML::Node* l = f.find("line");
  if (!l) {
    const YAML::Node* n = f.require("node");
    return n ? nodeRef(b, *n, f.path("node")) : std::nullopt;
  }
  const YAML::Node* end = f.find("end");
  const YAML::Node* node = f.find("node");
  const CaseLine* line = lineRef(b, *l, f.path("line"));
  if (end && node) {
    b.diag.error(*node, f.path("node") + ": given with end (expected either end: or node: K " +
                            "with line:)");
    return std::nullopt;
  }
  if (!end && !node) {
    b.diag.error(*l, f.path() + ": missing key 'end' (or 'node: K') with line: (expected a " +
                         "place on the line)");
    return std::nullopt;
  }
  if (!line || line->nodes.empty()) return std::nullopt;
  if (node) {
    const auto k = ordinal(b, *node, f.path("node"), *line, line->nodes.size(), "node");
    return k ? std::optional(line->nodes[*k]) : std::nullopt;
  }
  const auto last = lineEnd(b, *line, *end, f.path("end"));
  if (!last) return std::nullopt;
  return *last ? line->nodes.back() : line->nodes.front();
}

std::optional<ElementEndRef> elementEndOfEntry(
    CaseBuilder& b, Fields& f,
    const std::function<std::optional<int>(const YAML::Node&, const std::string&)>& element_id) {
  const YAML::Node* l = f.find("line");
  const YAML::Node* el = f.find("element");
  const YAML::Node* end = f.require("end");
  if (!l) {
    el = f.require("element");
    const auto element = el ? element_id(*el, f.path("element")) : std::nullopt;
    const auto which = end ? elementEnd(b, *end, f.path("end")) : std::nullopt;
    if (!element || !which) return std::nullopt;
    return ElementEndRef{*element, *which};
  }
  const CaseLine* line = lineRef(b, *l, f.path("line"));
  if (!line || !end) return std::nullopt;
  if (line->elements.empty()) {
    b.diag.error(*l, f.path("line") + ": line '" + line->name + "' has no elements (got a line " +
                         "without a section, expected a line of cable elements)");
    return std::nullopt;
  }
  if (el) {  // its K-th element, at the element's end
    const auto k = ordinal(b, *el, f.path("element"), *line, line->elements.size(), "element");
    const auto which = elementEnd(b, *end, f.path("end"));
    if (!k || !which) return std::nullopt;
    return ElementEndRef{line->elements[*k], *which};
  }
  const auto last = lineEnd(b, *line, *end, f.path("end"));  // the end element's outer end
  if (!last) return std::nullopt;
  return *last ? ElementEndRef{line->elements.back(), 1} : ElementEndRef{line->elements.front(), 0};
}

}  // namespace flexmoor::app
