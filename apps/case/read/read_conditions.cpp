// supports: and loads: of a case file, into the case's ConditionsSpec (apps/problem/
// conditions_spec.hpp). Prescribed displacements and static loads are reached at load factor 1
// (the steps move the load factor).
#include <algorithm>

#include "apps/case/case_builder.hpp"
#include "apps/case/input/physical_range.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const char* const kAxis[] = {"x", "y", "z"};

// The prescribed displacement of each fixed dof, in the order of `fix`: `displacement:` lists
// them in that order, or gives the full [x, y, z] with zeros at the free dofs. Zero by default.
std::optional<std::vector<double>> readPrescribed(CaseBuilder& b, Fields& f,
                                                  const std::vector<int>& fix) {
  const YAML::Node* n = f.find("displacement");
  if (!n) return std::vector<double>(fix.size(), 0.0);
  const std::string path = f.path("displacement");
  const bool in_fix_order = n->IsSequence() && n->size() == fix.size();
  if (!in_fix_order && !(n->IsSequence() && n->size() == 3)) {
    const std::string got =
        n->IsSequence() ? "a list of " + std::to_string(n->size()) : describeNode(*n);
    b.diag.error(*n, path + ": expected " + std::to_string(fix.size()) +
                         " lengths in the order of fix, or [x, y, z] (got " + got + ")");
    return std::nullopt;
  }
  std::vector<double> values(fix.size(), 0.0);
  bool ok = true;
  for (size_t i = 0; i < n->size(); ++i) {
    const int k = in_fix_order ? fix[i] : static_cast<int>(i);
    const auto value = b.in.quantity((*n)[i], childPath(path, kAxis[k]), kind::kLength);
    ok = ok && value.has_value();
    const auto slot = std::find(fix.begin(), fix.end(), k);
    if (slot != fix.end()) {
      values[slot - fix.begin()] = value.value_or(0.0);
    } else if (value && *value != 0.0) {
      b.diag.error((*n)[i], childPath(path, kAxis[k]) + ": " + kAxis[k] + " is not fixed (got " +
                                (*n)[i].Scalar() + ", expected 0 or " + kAxis[k] + " in fix)");
      ok = false;
    }
  }
  return ok ? std::optional(values) : std::nullopt;
}

// `history: NAME`: {true, the function} when absent (null) or found; {false, null} when wrong.
std::pair<bool, std::shared_ptr<const model::TimeFunction>> optionalHistory(CaseBuilder& b,
                                                                            const Fields& f) {
  const YAML::Node* h = f.find("history");
  if (!h) return {true, nullptr};
  auto history = historyRef(b, *h, f.path("history"));
  return {history != nullptr, history};
}

// A prescribed displacement with a history follows displacement * history(t) in dynamic steps.
void readSupport(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"node", "nodes", "fix", "displacement", "history"});
  const auto nodes = nodeOrNodes(b, f);
  const YAML::Node* fix_node = f.require("fix");
  const auto fix = fix_node ? readFix(b, *fix_node, f.path("fix")) : std::nullopt;
  const auto values = fix ? readPrescribed(b, f, *fix) : std::nullopt;
  const auto [history_ok, history] = optionalHistory(b, f);
  if (history && !f.find("displacement"))
    b.diag.error(*f.find("history"), f.path("history") +
                                         ": a history without a displacement moves nothing "
                                         "(expected displacement: with it)");
  if (!nodes || !values || !history_ok) return;
  bool reported = false;  // one message for a support however many of its dofs clash
  for (int node : *nodes)
    for (size_t i = 0; i < fix->size(); ++i) {
      const int k = (*fix)[i];
      const auto [first, added] =
          b.first_support.emplace(3LL * node + k, b.conditions.supports.size());
      if (added) {
        b.conditions.supports.push_back({node, k, (*values)[i], history, lineOf(item)});
        continue;
      }
      const SupportSpec& earlier = b.conditions.supports[first->second];
      const bool same = earlier.displacement == (*values)[i] && earlier.history == history;
      if (!same && !reported) {
        b.diag.error(item, path + ": node " + std::to_string(b.c.node_ids[node]) + " " + kAxis[k] +
                               " is prescribed twice, differently (got " +
                               formatNumber((*values)[i]) + (history ? " with a history" : "") +
                               " here and " + formatNumber(earlier.displacement) +
                               (earlier.history ? " with a history" : "") + " on line " +
                               std::to_string(earlier.line) +
                               ", expected one prescribed displacement a dof)");
        reported = true;
      }
    }
}

void readNodalLoad(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"node", "nodes", "force", "history"});
  const auto nodes = nodeOrNodes(b, f);
  const YAML::Node* force_node = f.require("force");
  const auto force =
      force_node ? b.in.vector3(*force_node, f.path("force"), kind::kForce) : std::nullopt;
  const auto [history_ok, history] = optionalHistory(b, f);
  if (!nodes || !force || !history_ok) return;
  for (int node : *nodes) b.conditions.nodal_loads.push_back({node, *force, history});
}

}  // namespace

// The membranes of the surfaces that `on:` names (case_builder.hpp).
std::optional<std::vector<int>> surfaceMembranes(CaseBuilder& b, const YAML::Node& on,
                                                 const std::string& path) {
  std::vector<int> elements;
  bool ok = true;
  const std::vector<YAML::Node> names = listOrOne(b.diag, on, path);
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string where = listOrOnePath(on, path, i);
    const auto name = b.in.text(names[i], where);
    const auto set = name ? b.c.element_sets.find(*name) : b.c.element_sets.end();
    if (name && set == b.c.element_sets.end() && !b.broken_node_names.count(*name))
      b.diag.error(names[i], where + ": unknown surface (got '" + *name + "', expected " +
                                 nameList(b.c.element_sets) + ")");
    ok = ok && set != b.c.element_sets.end();
    if (set == b.c.element_sets.end()) continue;
    for (int e : set->second)  // the membranes only, not the surface's cables
      if (b.element_types[e] == "membrane" || b.element_types[e] == "axisymmetric_membrane")
        elements.push_back(e);
  }
  if (!ok) return std::nullopt;
  return elements;
}

namespace {

// A follower pressure (Eq. 3.30-3.37) on the membranes of surfaces: `on: SURFACE` or a list of
// surfaces, acting along the surface normal (s-direction x t-direction of its parameters).
void readPressure(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"on", "pressure", "history"});
  const YAML::Node* on = f.require("on");
  const YAML::Node* p = f.require("pressure");
  const auto pressure = p ? b.in.quantity(*p, f.path("pressure"), kind::kPressure) : std::nullopt;
  const auto [history_ok, history] = optionalHistory(b, f);
  const auto elements = on ? surfaceMembranes(b, *on, f.path("on")) : std::nullopt;
  if (!elements || !pressure || !history_ok) return;
  b.conditions.pressures.push_back({*elements, *pressure, history});
}

// The incident wave pressure of the sea on the membranes of surfaces (built with the ocean,
// build_ocean.cpp): `on:` as for a pressure, and `water_side:` positive (the side the surface
// normal s x t points to: outside a body whose normals point out) or negative.
void readWavePressure(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"on", "water_side"});
  const YAML::Node* on = f.require("on");
  const YAML::Node* side_node = f.require("water_side");
  const auto side = side_node
                        ? b.in.choice<hydro::WaterSide>(*side_node, f.path("water_side"),
                                                        {{"positive", hydro::WaterSide::Positive},
                                                         {"negative", hydro::WaterSide::Negative}})
                        : std::nullopt;
  const auto elements = on ? surfaceMembranes(b, *on, f.path("on")) : std::nullopt;
  if (!elements || !side) return;
  b.ocean.wave_pressures.push_back({*elements, *side, lineOf(item), path});
}

// gravity: [gx, gy, gz], or {g: G} for (0, 0, -G); its magnitude within kGravityRange.
void readGravity(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  if (n.IsMap()) {
    Fields f(b.diag, n, path, {"g"});
    const YAML::Node* g = f.require("g");
    auto value =
        g ? b.in.quantity(*g, f.path("g"), kind::kAcceleration, Limit::NonNegative) : std::nullopt;
    if (value && !inPhysicalRange(b.in, *g, f.path("g"), *value, kGravityRange)) value.reset();
    if (value) b.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -*value);
    b.gravity_given = value.has_value();
    return;
  }
  auto g = b.in.vector3(n, path, kind::kAcceleration);
  if (g && !inPhysicalRange(b.in, n, path, g->norm(), kGravityRange,
                            "a magnitude of " + formatNumber(g->norm()) + " " +
                                unitNames(b.in.units).length + "/s^2"))
    g.reset();
  if (g) b.conditions.gravity = *g;
  b.gravity_given = g.has_value();
}

}  // namespace

// fix: [x, z] -> {0, 2} (also a step's release: dofs).
std::optional<std::vector<int>> readFix(CaseBuilder& b, const YAML::Node& n,
                                        const std::string& path) {
  if (!n.IsSequence() || n.size() < 1 || n.size() > 3) {
    b.diag.error(n, path + ": expected a list of the dofs to fix, from x, y, z (got " +
                        describeNode(n) + ")");
    return std::nullopt;
  }
  std::vector<int> fix;
  for (size_t i = 0; i < n.size(); ++i) {
    const auto k = b.in.choice<int>(n[i], itemPath(path, i), {{"x", 0}, {"y", 1}, {"z", 2}});
    if (!k) return std::nullopt;
    if (std::find(fix.begin(), fix.end(), *k) != fix.end()) {
      b.diag.error(n[i], itemPath(path, i) + ": " + kAxis[*k] + " is given twice");
      return std::nullopt;
    }
    fix.push_back(*k);
  }
  return fix;
}

void readSupports(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "supports");
  for (size_t i = 0; i < items.size(); ++i) readSupport(b, items[i], itemPath("supports", i));
}

void readLoads(CaseBuilder& b, const YAML::Node& n) {
  Fields f(b.diag, n, "loads", {"gravity", "nodal", "pressure", "wave_pressure", "enclosed_fluid"});
  if (const YAML::Node* g = f.find("gravity")) readGravity(b, *g, f.path("gravity"));
  // Each item of the list under `key`, read by `read` with its path.
  using ItemReader = void (*)(CaseBuilder&, const YAML::Node&, const std::string&);
  const auto each = [&](const char* key, ItemReader read) {
    const YAML::Node* list = f.find(key);
    if (!list) return;
    const std::vector<YAML::Node> items = listItems(b.diag, *list, f.path(key));
    for (size_t i = 0; i < items.size(); ++i) read(b, items[i], itemPath(f.path(key), i));
  };
  each("nodal", readNodalLoad);
  each("pressure", readPressure);
  each("wave_pressure", readWavePressure);
  each("enclosed_fluid", readEnclosedFluid);
}

}  // namespace flexmoor::app
