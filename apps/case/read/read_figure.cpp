// figure: of a case file: the time series a run draws as a PNG (flexmoor plot).
//   figure:
//     title: Example 8, buoy released          # optional; default the case's title
//     series:
//       - {quantity: position_x, node: cable.end}
//       - {quantity: speed, node: cable.end}
//       - {quantity: tension_end, element: 1, end: first}   # end: first | last | 1 | 2
//       - {quantity: tension_end, line: moor, end: fairlead}  # a line's end (line_refs.cpp)
//   figure: {kind: mooring}    # every anchored line's fairlead tension and the lines' profiles
//                              # (a spread mooring's figure when the case gives none)
#include <algorithm>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

// What a series may show: node variables of the netCDF file (and the speed |u'| the plot derives
// from the velocity), and the end tension of a cable or spring.
const std::vector<std::string>& nodeQuantities() {
  static const std::vector<std::string> q = {
      "position_x",     "position_y", "position_z", "displacement_x", "displacement_y",
      "displacement_z", "velocity_x", "velocity_y", "velocity_z",     "speed",
      "reaction_x",     "reaction_y", "reaction_z"};
  return q;
}

std::optional<std::string> readSeries(CaseBuilder& b, const YAML::Node& item,
                                      const std::string& path) {
  Fields f(b.diag, item, path, {"quantity", "node", "element", "end", "line"});
  const YAML::Node* q = f.require("quantity");
  const auto quantity = q ? b.in.text(*q, f.path("quantity")) : std::nullopt;
  if (!quantity) return std::nullopt;
  const auto& nodal = nodeQuantities();
  const bool is_node = std::find(nodal.begin(), nodal.end(), *quantity) != nodal.end();
  if (!is_node && *quantity != "tension_end") {
    std::string expected;
    for (const std::string& n : nodal) expected += n + ", ";
    b.diag.error(*q, f.path("quantity") + ": not a series of a figure (got '" + *quantity +
                         "', expected one of " + expected + "tension_end)");
    return std::nullopt;
  }
  // A series is drawn from the netCDF file: its field must be written.
  const OutputField field = *OutputFields::ofVariable(*quantity);
  if (!b.c.output.has(field)) {
    b.diag.error(*q, f.path("quantity") + ": " + *quantity + " is not written (output: fields: " +
                         "does not list " + std::string(OutputFields::name(field)) + ")");
    return std::nullopt;
  }
  const bool on_line = f.find("line") != nullptr;
  for (const char* key : {"node", "element", "end"}) {
    const bool used = is_node ? std::string(key) == "node" || (std::string(key) == "end" && on_line)
                              : std::string(key) != "node";
    if (f.find(key) && !used) {
      b.diag.error(*f.find(key), f.path(key) + ": not used by " + *quantity +
                                     (is_node && std::string(key) == "end"
                                          ? " without line: (expected line: NAME with end:)"
                                          : ""));
      return std::nullopt;
    }
  }
  if (is_node) {
    const auto node = nodeOfEntry(b, f);
    if (!node) return std::nullopt;
    return FigureSpec::nodeSeries(*quantity, *node);
  }
  const int count = static_cast<int>(b.element_types.size());
  const auto element_id = [&](const YAML::Node& e, const std::string& at) -> std::optional<int> {
    if (count == 0) return std::nullopt;  // no elements: reported by readCase
    const auto id = b.in.integer(e, at, 1, count);
    if (!id) return std::nullopt;
    const std::string& type = b.element_types[*id - 1];
    if (type == "cable" || type == "spring") return *id - 1;
    if (!type.empty())
      b.diag.error(e, at + ": element " + std::to_string(*id) + " is a " + type +
                          " (expected a cable or spring)");
    return std::nullopt;
  };
  std::optional<ElementEndRef> at;
  if (!on_line && !f.find("end")) {  // an element's first end unless end: says
    const YAML::Node* e = f.require("element");
    const auto element = e ? element_id(*e, f.path("element")) : std::nullopt;
    if (element) at = ElementEndRef{*element, 0};
  } else {
    at = elementEndOfEntry(b, f, element_id);
  }
  if (!at) return std::nullopt;
  return FigureSpec::tensionSeries(at->element, at->end);
}

// Whether the case has a line with an anchor end (what a mooring figure draws).
bool anchoredLine(const CaseBuilder& b) {
  return std::any_of(b.c.named_lines.begin(), b.c.named_lines.end(),
                     [](const CaseLine& l) { return l.anchor != CaseLine::Anchor::None; });
}

}  // namespace

void readFigure(CaseBuilder& b, const YAML::Node& n) {
  if (n.IsNull()) return;
  Fields f(b.diag, n, "figure", {"title", "kind", "series"});
  FigureSpec figure;
  figure.where = {b.diag.file(), lineOf(n)};
  if (const YAML::Node* t = f.find("title"))
    figure.title = b.in.text(*t, f.path("title")).value_or("");
  if (const YAML::Node* k = f.find("kind"))
    figure.kind = b.in.choice<FigureSpec::Kind>(*k, f.path("kind"),
                                                {{"series", FigureSpec::Kind::Series},
                                                 {"mooring", FigureSpec::Kind::Mooring}})
                      .value_or(figure.kind);
  if (figure.kind == FigureSpec::Kind::Mooring) {
    if (const YAML::Node* s = f.find("series"))
      b.diag.error(*s, f.path("series") +
                           ": not a key of a mooring figure (got series, expected "
                           "kind: series for time series of your choice)");
    else if (!anchoredLine(b))
      b.diag.error(n,
                   "figure: a mooring figure needs a line with an anchor (got none, expected "
                   "mooring_lines: or a line with anchor: start | end)");
    else
      b.c.figure = std::move(figure);
    return;
  }
  const YAML::Node* list = f.require("series");
  if (!list) return;
  const std::vector<YAML::Node> items = listItems(b.diag, *list, f.path("series"));
  if (items.empty())
    b.diag.error(*list, f.path("series") + ": no series (expected at least one {quantity, node})");
  bool ok = !items.empty();
  for (size_t i = 0; i < items.size(); ++i) {
    const auto spec = readSeries(b, items[i], itemPath(f.path("series"), i));
    ok = ok && spec.has_value();
    if (spec) figure.series.push_back(*spec);
  }
  if (ok) b.c.figure = std::move(figure);
}

}  // namespace flexmoor::app
