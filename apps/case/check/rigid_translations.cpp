#include "apps/case/check/rigid_translations.hpp"

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "libstruct/element/spring_element.hpp"

namespace flexmoor::app {
namespace {

constexpr int kX = 1, kZ = 4, kAll = 7;

bool needsStiffness(const StepSpec& step) { return step.kind != StepSpec::Kind::Dynamic; }

// The vertical hold of a group by its loads: its net upward force at rest, fully submerged
// (buoyancy less weight, plus the nodal loads), whether any of it touches the bed, and whether
// its buoyancy falls as it rises through the surface.
struct VerticalLoads {
  double upward = 0.0;
  bool touches_bed = false;
  bool floats = false;
};

// An element's mass that weighs: the sum of its consistent mass matrix over the vertical dofs
// (Eq. 4.40, 4.49: its total mass), a point mass's own (a liquid's lumped mass weighs nothing).
double weighingMass(const CheckedModel& k, int e, const model::State& state, Eigen::MatrixXd& M) {
  const element::Element& element = k.model().element(e);
  if (const auto* point = dynamic_cast<const element::PointMassElement*>(&element))
    return point->weighingMass();
  element.mass({k.model().reference(), state, e}, element::MassKind::Consistent, M);
  const int n = static_cast<int>(element.nodes().size());
  double mass = 0.0;
  for (int I = 0; I < n; ++I)
    for (int J = 0; J < n; ++J) mass += M(3 * I + 2, 3 * J + 2);
  return mass;
}

// A line's reference length: the chords between its nodes (exact for straight elements).
double referenceLength(const CheckedModel& k, int e) {
  const std::vector<int>& nodes = k.model().element(e).nodes();
  double length = 0.0;
  for (size_t i = 1; i < nodes.size(); ++i)
    length +=
        (k.model().reference().col(nodes[i]) - k.model().reference().col(nodes[i - 1])).norm();
  return length;
}

// The vertical loads of the groups in `of` (by their roots).
std::map<int, VerticalLoads> verticalLoads(const CheckedModel& k, const std::vector<int>& root,
                                           const std::set<int>& of) {
  std::map<int, VerticalLoads> loads;
  const OceanSpec& h = k.ocean;
  const double g_z = k.model().gravity().z();
  const double buoyancy = h.has_water ? h.water.density * h.water.gravity : 0.0;  // per volume
  const model::State state = k.model().initialState();
  Eigen::MatrixXd M;
  const std::vector<const LineHydroSpec*> hydro = h.elementHydro(k.model().elementCount());
  for (int e = 0; e < k.model().elementCount(); ++e) {
    const int r = root[k.model().element(e).nodes().front()];
    if (!of.count(r)) continue;  // a point mass off every group, or a group held vertically
    VerticalLoads& v = loads[r];
    v.upward += weighingMass(k, e, state, M) * g_z;
    if (!hydro[e] || k.mesh.elements[e].kind != ElementSpec::Kind::Cable || !h.has_water) continue;
    const double d = hydro[e]->coefficients.diameter;
    v.upward += buoyancy * M_PI * d * d / 4.0 * referenceLength(k, e);
    v.floats = true;  // a point above the surface carries no buoyancy
    v.touches_bed = v.touches_bed || h.has_contact;
  }
  for (const BodySpec& body : h.bodies) {
    if (!of.count(root[body.node])) continue;
    VerticalLoads& v = loads[root[body.node]];
    v.upward += buoyancy * body.body.volume;
    v.floats = v.floats || body.body.diameter > 0.0;  // a sphere's cap; a point body: all or none
    v.touches_bed = v.touches_bed || (h.has_contact && body.body.volume > 0.0);
  }
  for (const model::NodalLoad& load : k.model().nodalLoads())
    if (of.count(root[load.node])) loads[root[load.node]].upward += load.force.z();
  return loads;
}

// The directions supports fix on each group, the supports `released` let go holding nothing.
std::map<int, int> supported(const CheckedModel& k, const std::vector<int>& root,
                             const std::set<std::pair<int, int>>& released) {
  std::map<int, int> fixed;
  for (int node = 0; node < k.model().nodeCount(); ++node) {
    if (root[node] < 0) continue;
    int& mask = fixed[root[node]];
    for (int d = 0; d < 3; ++d)
      if (k.model().isConstrained(node, d) && !released.count({node, d})) mask |= 1 << d;
  }
  return fixed;
}

}  // namespace

std::vector<UnrestrainedGroup> unrestrainedGroups(const CheckedModel& k,
                                                  const std::vector<int>& root) {
  // The directions supports fix on each group in each step, after the releases up to it.
  std::vector<std::map<int, int>> fixed;
  std::set<std::pair<int, int>> released;
  for (const StepSpec& step : k.c.steps) {
    const bool more = !step.release.empty();
    released.insert(step.release.begin(), step.release.end());
    fixed.push_back(fixed.empty() || more ? supported(k, root, released) : fixed.back());
  }
  const std::map<int, int> initial = supported(k, root, {});

  // What holds the groups but supports, and the text that says so: radially the hoop
  // stiffness, vertically the bed or the surface for the groups some step leaves free in z.
  std::map<int, int> other;
  std::map<int, std::string> other_text;
  for (const auto& element : k.model().elements())
    if (element->typeName().rfind("axisymmetric", 0) == 0 || element->typeName() == "hoop_cable") {
      const int r = root[element->nodes().front()];
      if (r >= 0 && !(other[r] & kX)) {
        other[r] |= kX;
        other_text[r] = "its x (the radius) held by the hoop stiffness";
      }
    }
  std::set<int> free_in_z;
  for (const std::map<int, int>& step : fixed)
    for (const auto& [r, mask] : step)
      if (!(mask & kZ)) free_in_z.insert(r);
  for (const auto& [r, v] : verticalLoads(k, root, free_in_z)) {
    const char* by = v.upward < 0.0 && v.touches_bed ? "the seabed its weight in water rests it on"
                     : v.upward > 0.0 && v.floats ? "the water's surface its buoyancy floats it at"
                                                  : nullptr;
    if (!by) continue;
    other[r] |= kZ;
    other_text[r] += (other_text[r].empty() ? "" : ", ") + std::string("its z held by ") + by;
  }

  // Each group's first step that needs a stiffness and leaves a direction free, else its first
  // dynamic step that does.
  std::map<int, UnrestrainedGroup> found;
  for (size_t i = 0; i < k.c.steps.size(); ++i) {
    const bool stiff = needsStiffness(k.c.steps[i]);
    for (const auto& [r, mask] : fixed[i]) {
      const int free = kAll & ~(mask | other[r]);
      if (free == 0) continue;
      const auto [it, added] = found.try_emplace(r);
      UnrestrainedGroup& g = it->second;
      if (!added && (g.step >= 0 || !stiff)) continue;
      g.root = r;
      g.free = free;
      g.step = stiff ? static_cast<int>(i) : -1;
      g.released = (free & initial.at(r)) != 0;
      g.held_other = other_text[r];
    }
  }
  std::vector<UnrestrainedGroup> groups;
  for (const auto& [r, g] : found) groups.push_back(g);
  return groups;
}

}  // namespace flexmoor::app
