// figure: of a case file: the time series a run draws as a PNG (flexmoor plot).
//   figure:
//     title: Example 8, buoy released          # optional; default the case's title
//     series:
//       - {quantity: position_x, node: cable.end}
//       - {quantity: speed, node: cable.end}
//       - {quantity: tension_end, element: 1, end: 1}
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
  Fields f(b.diag, item, path, {"quantity", "node", "element", "end"});
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
  if (is_node) {
    const YAML::Node* n = f.require("node");
    const auto node = n ? nodeRef(b, *n, f.path("node")) : std::nullopt;
    if (!node) return std::nullopt;
    return *quantity + "@node=" + std::to_string(*node + 1);
  }
  const YAML::Node* e = f.require("element");
  const int count = static_cast<int>(b.element_types.size());
  const int end = b.in.integerOr(f, "end", 1, 1);
  if (f.find("end") && end > 2)
    b.diag.error(*f.find("end"),
                 f.path("end") + ": out of range (got " + std::to_string(end) +
                     ", expected 1 for the element's first node or 2 for its last)");
  if (!e || count == 0) return std::nullopt;  // no elements: reported by readCase
  const int element = b.in.integer(*e, f.path("element"), 1, count).value_or(0);
  if (element == 0) return std::nullopt;
  const std::string& type = b.element_types[element - 1];
  if (type != "cable" && type != "spring") {
    b.diag.error(*e, f.path("element") + ": element " + std::to_string(element) + " is a " + type +
                         " (expected a cable or spring)");
    return std::nullopt;
  }
  return "tension_end@element=" + std::to_string(element) + ",end=" + std::to_string(end);
}

}  // namespace

void readFigure(CaseBuilder& b, const YAML::Node& n) {
  if (n.IsNull()) return;
  Fields f(b.diag, n, "figure", {"title", "series"});
  FigureSpec figure;
  figure.where = {b.diag.file(), lineOf(n)};
  if (const YAML::Node* t = f.find("title"))
    figure.title = b.in.text(*t, f.path("title")).value_or("");
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
