// summary: of a case file: the named scalars a run reports in summary.json.
#include <charconv>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

using Quantity = SummarySpec::Quantity;

// What a quantity is measured on.
enum class Target { Node, Element, Model };

struct QuantityInfo {
  Quantity quantity;
  int component;
  bool is_length;  // else a force
  Target target;
};

const std::vector<std::pair<std::string, QuantityInfo>>& quantities() {
  static const std::vector<std::pair<std::string, QuantityInfo>> table = {
      {"displacement_x", {Quantity::Displacement, 0, true, Target::Node}},
      {"displacement_y", {Quantity::Displacement, 1, true, Target::Node}},
      {"displacement_z", {Quantity::Displacement, 2, true, Target::Node}},
      {"position_x", {Quantity::Position, 0, true, Target::Node}},
      {"position_y", {Quantity::Position, 1, true, Target::Node}},
      {"position_z", {Quantity::Position, 2, true, Target::Node}},
      {"reaction_x", {Quantity::Reaction, 0, false, Target::Node}},
      {"reaction_y", {Quantity::Reaction, 1, false, Target::Node}},
      {"reaction_z", {Quantity::Reaction, 2, false, Target::Node}},
      {"reaction_magnitude", {Quantity::ReactionMagnitude, 0, false, Target::Node}},
      {"end_tension", {Quantity::EndTension, 0, false, Target::Element}},
      {"max_tension", {Quantity::MaxTension, 0, false, Target::Model}},
  };
  return table;
}

// `step: NAME` or `step: INDEX` (1-based) -> 0-based step index.
std::optional<int> stepRef(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  const int count = static_cast<int>(b.c.steps.size());
  int index = 0;
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), index);
  if (error == std::errc() && end == s.data() + s.size()) {
    const auto checked = b.in.integer(n, path, 1, std::max(count, 1));
    return checked ? std::optional(*checked - 1) : std::nullopt;
  }
  std::vector<int> matches;
  std::string names;
  for (int i = 0; i < count; ++i) {
    if (b.c.steps[i].name == s) matches.push_back(i);
    names += (names.empty() ? "" : ", ") + b.c.steps[i].name;
  }
  if (matches.size() == 1) return matches[0];
  b.diag.error(n, path + (matches.empty() ? ": unknown step" : ": several steps have this name") +
                      " (got " + describeNode(n) + ", expected a step index from 1 to " +
                      std::to_string(count) + " or a unique step name: " + names + ")");
  return std::nullopt;
}

// `element: ID` (1-based, explicit elements first, then line elements) of a cable or spring.
std::optional<int> tensionElement(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  const int count = static_cast<int>(b.element_types.size());
  const auto id = b.in.integer(n, path, 1, std::max(count, 1));
  if (!id) return std::nullopt;
  const std::string& type = b.element_types[*id - 1];
  if (type == "point_mass")
    b.diag.error(n, path + ": element " + n.Scalar() +
                        " carries no tension (got a point_mass, expected a cable or spring)");
  if (type == "cable" || type == "spring") return *id - 1;
  return std::nullopt;
}

// A reaction is zero at a free dof: asking for one there is a mistake.
bool checkReaction(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                   const SummarySpec& s) {
  const model::Model& m = b.model;
  if (s.quantity == Quantity::Reaction && !m.isConstrained(s.node, s.component)) {
    b.diag.error(n, path + ": the reaction is zero (got a node whose " + "xyz"[s.component] +
                        " is free, expected a fixed dof)");
    return false;
  }
  const bool any =
      m.isConstrained(s.node, 0) || m.isConstrained(s.node, 1) || m.isConstrained(s.node, 2);
  if (s.quantity == Quantity::ReactionMagnitude && !any) {
    b.diag.error(n, path +
                        ": the reaction is zero (got a node without support, expected a node "
                        "with a fixed dof)");
    return false;
  }
  return true;
}

// Every key a quantity does not use is an error, so that a misplaced key is not ignored.
bool rejectUnused(CaseBuilder& b, Fields& f, const std::string& quantity, Target target) {
  bool ok = true;
  for (const char* key : {"node", "element", "end"}) {
    const bool used =
        std::string(key) == "node" ? target == Target::Node : target == Target::Element;
    if (f.find(key) && !used) {
      b.diag.error(*f.find(key), f.path(key) + ": not used by " + quantity);
      ok = false;
    }
  }
  return ok;
}

std::optional<SummarySpec> readQuantity(CaseBuilder& b, const MapEntry& e) {
  Fields f(b.diag, e.value, childPath("summary", e.key),
           {"quantity", "node", "element", "end", "scale", "step"});
  SummarySpec s;
  s.name = e.key;
  s.where = {b.diag.file(), lineOf(e.key_node)};
  const YAML::Node* q = f.require("quantity");
  const auto chosen = q ? b.in.choice(*q, f.path("quantity"), quantities()) : std::nullopt;
  s.scale = b.in.quantityOr(f, "scale", kind::kNumber, Limit::Any, 1.0);
  std::optional<int> step = -1;  // the last step
  if (const YAML::Node* n = f.find("step")) step = stepRef(b, *n, f.path("step"));
  if (!chosen) return std::nullopt;
  const QuantityInfo info = *chosen;
  if (!rejectUnused(b, f, q->Scalar(), info.target)) return std::nullopt;
  s.quantity = info.quantity;
  s.component = info.component;
  const UnitNames units = unitNames(b.in.units);
  s.unit = info.is_length ? units.length : units.force;
  if (info.target == Target::Node) {
    const YAML::Node* n = f.require("node");
    const auto node = n ? nodeRef(b, *n, f.path("node")) : std::nullopt;
    if (!node) return std::nullopt;
    s.node = *node;
    if (!checkReaction(b, *n, f.path("node"), s)) return std::nullopt;
  }
  if (info.target == Target::Element) {
    const YAML::Node* el = f.require("element");
    const YAML::Node* end = f.require("end");
    const auto element = el ? tensionElement(b, *el, f.path("element")) : std::nullopt;
    const auto which =
        end ? b.in.choice<int>(*end, f.path("end"), {{"first", 0}, {"last", 1}}) : std::nullopt;
    if (!element || !which) return std::nullopt;
    s.element = *element;
    s.end = *which;
  }
  if (!step) return std::nullopt;
  s.step = *step;
  return s;
}

}  // namespace

void readSummary(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "summary"))
    if (auto spec = readQuantity(b, e)) b.c.summary.push_back(std::move(*spec));
}

}  // namespace flexmoor::app
