// supports: and loads: of a case file. Prescribed displacements and static loads are reached at
// load factor 1 (the steps move the load factor).
#include <algorithm>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

const char* const kAxis[] = {"x", "y", "z"};

// fix: [x, z] -> {0, 2}
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

void readSupport(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"node", "nodes", "fix", "displacement"});
  const auto nodes = nodeOrNodes(b, f);
  const YAML::Node* fix_node = f.require("fix");
  const auto fix = fix_node ? readFix(b, *fix_node, f.path("fix")) : std::nullopt;
  const auto values = fix ? readPrescribed(b, f, *fix) : std::nullopt;
  if (!nodes || !values) return;
  for (int node : *nodes)
    for (size_t i = 0; i < fix->size(); ++i) b.model.constrain(node, (*fix)[i], (*values)[i]);
}

void readNodalLoad(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"node", "nodes", "force"});
  const auto nodes = nodeOrNodes(b, f);
  const YAML::Node* force_node = f.require("force");
  const auto force =
      force_node ? b.in.vector3(*force_node, f.path("force"), kind::kForce) : std::nullopt;
  if (!nodes || !force) return;
  for (int node : *nodes) b.model.addNodalLoad(node, *force);
}

// gravity: [gx, gy, gz], or {g: G} for (0, 0, -G).
void readGravity(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  if (n.IsMap()) {
    Fields f(b.diag, n, path, {"g"});
    const YAML::Node* g = f.require("g");
    const auto value =
        g ? b.in.quantity(*g, f.path("g"), kind::kAcceleration, Limit::NonNegative) : std::nullopt;
    if (value) b.model.setGravity(Eigen::Vector3d(0.0, 0.0, -*value));
    return;
  }
  if (const auto g = b.in.vector3(n, path, kind::kAcceleration)) b.model.setGravity(*g);
}

}  // namespace

void readSupports(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "supports");
  for (size_t i = 0; i < items.size(); ++i) readSupport(b, items[i], itemPath("supports", i));
}

void readLoads(CaseBuilder& b, const YAML::Node& n) {
  Fields f(b.diag, n, "loads", {"gravity", "nodal"});
  if (const YAML::Node* g = f.find("gravity")) readGravity(b, *g, f.path("gravity"));
  if (const YAML::Node* nodal = f.find("nodal")) {
    const std::vector<YAML::Node> items = listItems(b.diag, *nodal, f.path("nodal"));
    for (size_t i = 0; i < items.size(); ++i)
      readNodalLoad(b, items[i], itemPath(f.path("nodal"), i));
  }
}

}  // namespace flexmoor::app
