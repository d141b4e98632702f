// The checks of a case's built model and steps (model_checks.hpp): what would make a
// run fail obscurely or give a wrong number, refused with the line of the element, node or step.
//   geometry   every element's Jacobian positive at its integration points
//              (Element::minRelativeJacobian)
//   mechanisms a free dof that no element holds; a group of nodes joined by elements that
//              nothing holds in x, y or z in a relax, static or modes step (a rigid translation:
//              no support, the supports released, no seabed or surface to hold it vertically;
//              rigid_translations.hpp), a warning when only dynamic steps see it free. Only
//              these topological mechanisms: a taut net supported at its ends has a singular
//              initial stiffness too (its cables start slack), which viscous relaxation is
//              there for.
//   coincident two nodes at one point that no element joins: part of the error when they leave
//              a mechanism, else a warning (the model runs, but perhaps not as meant).
//   steps      modes and dynamic steps need a mass on every free dof; no more modes than free
//              dofs; a warning for a time step too long for a periodic history or a wave it is
//              driven by.
//   ocean      no node and no body below the seabed; Morison loads and axial damping on lines
//              only.
#include "apps/case/check/model_checks.hpp"

#include <algorithm>
#include <numeric>
#include <set>

#include "apps/case/build/node_index.hpp"
#include "apps/case/check/rigid_translations.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const char* const kAxis[] = {"x", "y", "z"};

// Below this Jacobian relative to a regular element's (reference_jacobian.hpp) an element has
// collapsed: its stiffness would be 1e8 times that of a well-shaped one, or infinite.
constexpr double kCollapsed = 1e-8;

// Fewer time steps than this in a period of a history do not resolve it (the trapezoidal
// rule's period error is about (pi^2 / 12) (dt / T)^2: 8% at 10 steps a period).
constexpr double kStepsPerPeriod = 10.0;

// Messages and warnings beyond this many of one kind are summed up in one line.
constexpr int kMaxReported = 20;

std::string nodeName(const CheckedModel& k, int node) {
  return "node " + std::to_string(k.c.node_ids[node]);
}

std::string elementName(const CheckedModel& k, int e) {
  return "element " + std::to_string(e + 1) + " (" + k.model().element(e).typeName() + " of " +
         k.origins.elements[e].where + ")";
}

std::string stepName(const StepSpec& step) { return "step '" + step.name + "'"; }

bool isLine(const element::Element& e) {
  return e.typeName().rfind("cable", 0) == 0 || e.typeName().rfind("axisymmetric", 0) == 0;
}

void checkGeometry(const CheckedModel& k) {
  for (int e = 0; e < k.model().elementCount(); ++e) {
    const element::Element& element = k.model().element(e);
    const double J = element.minRelativeJacobian(k.model().reference());
    if (J > kCollapsed) continue;
    const bool axisymmetric = element.typeName().rfind("axisymmetric", 0) == 0;
    const std::string hint =
        isLine(element) ? std::string("are its middle nodes strictly between its ends, in order") +
                              (axisymmetric ? ", and its points at x > 0 (the radius)?" : "?")
                        : "are its nodes in order around it, and not on one line?";
    k.diag.error(k.origins.elements[e].line,
                 elementName(k, e) + ": " +
                     (isLine(element) ? "folded or collapsed" : "inverted or collapsed") +
                     ": its Jacobian is not positive at every integration point (got " +
                     formatNumber(J) + " relative to a regular element's, expected > 0; " + hint +
                     ")");
  }
}

// Nodes joined through elements (springs and cables alike; a point mass joins nothing).
class Components {
 public:
  explicit Components(int nodes) : parent_(nodes) { std::iota(parent_.begin(), parent_.end(), 0); }
  int root(int n) {
    while (parent_[n] != n) n = parent_[n] = parent_[parent_[n]];
    return n;
  }
  void join(int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the root is the smallest node
  }

 private:
  std::vector<int> parent_;
};

// For each node, another node at the same point that no element joins to it (or -1).
std::vector<int> unjoinedTwins(const CheckedModel& k,
                               const std::vector<std::vector<int>>& adjacent) {
  const model::NodalField& X = k.model().reference();
  std::vector<int> twin(X.cols(), -1);
  if (X.cols() == 0) return twin;
  const double tolerance = k.mesh.positionTolerance();
  if (!(tolerance > 0.0)) return twin;
  const NodeIndex index(X, tolerance);
  const auto joined = [&](int a, int c) {
    for (int e : adjacent[a])
      for (int n : k.model().element(e).nodes())
        if (n == c) return true;
    return false;
  };
  for (int node = 0; node < X.cols(); ++node)
    index.visitNear(X.col(node), [&](int other) {
      if (other == node || joined(node, other)) return true;
      twin[node] = other;
      return false;
    });
  return twin;
}

std::string twinHint(const CheckedModel& k, int node, int twin) {
  return "; " + nodeName(k, node) + " is at the same point as " + nodeName(k, twin) + " (line " +
         std::to_string(k.origins.node_lines[twin]) +
         "), which no element joins to it: did you mean them merged into one node?";
}

// The named lines and surfaces a group of nodes (by its root) holds, for the messages.
std::string namesOf(const CheckedModel& k, Components& parts, int root) {
  std::string names;
  const auto add = [&](const char* what, const std::map<std::string, std::vector<int>>& sets) {
    for (const auto& [name, nodes] : sets)
      if (!nodes.empty() && parts.root(nodes.front()) == root)
        names += (names.empty() ? "" : ", ") + std::string(what) + " '" + name + "'";
  };
  add("line", k.c.lines);
  add("surface", k.surfaces);
  return names;
}

// How the messages name a group of joined nodes, and the line of the file that defines it: its
// first named line (in the file's order), else its surface, else its smallest node.
struct GroupName {
  std::string text;
  int line;
  std::string is;  // "is" or "are"
};

GroupName groupName(const CheckedModel& k, Components& parts, int root, int size) {
  const std::string names = namesOf(k, parts, root);
  const std::string nodes = std::to_string(size) + " nodes";
  if (names.empty())
    return {nodeName(k, root) + " and the " +
                (size == 2 ? std::string("node") : std::to_string(size - 1) + " nodes") +
                " joined to it by elements",
            k.origins.node_lines[root], "are"};
  int line = k.origins.node_lines[root];
  for (const CaseLine& named : k.c.named_lines)
    if (!named.nodes.empty() && parts.root(named.nodes.front()) == root) {
      line = k.origins.node_lines[named.nodes.front()];
      break;
    }
  const bool one = names.find(", ") == std::string::npos;
  return {(one ? names : "the group of " + names) + " (" + nodes + ")", line, "is"};
}

void checkMechanisms(const CheckedModel& k) {
  const int count = k.model().nodeCount();
  std::vector<std::vector<int>> adjacent(count);  // elements at each node
  Components parts(count);
  std::vector<bool> held(count, false);
  for (int e = 0; e < k.model().elementCount(); ++e) {
    const element::Element& element = k.model().element(e);
    if (element.typeName() == "point_mass") continue;
    for (int n : element.nodes()) {
      adjacent[n].push_back(e);
      held[n] = true;
      parts.join(element.nodes().front(), n);
    }
  }
  const std::vector<int> twin = unjoinedTwins(k, adjacent);

  // Free dofs of nodes that no element holds.
  for (int node = 0; node < count; ++node) {
    std::string free;
    for (int d = 0; d < 3; ++d)
      if (!k.model().isConstrained(node, d))
        free += (free.empty() ? "" : ", ") + std::string(kAxis[d]);
    if (held[node] || free.empty()) continue;
    k.diag.error(k.origins.node_lines[node],
                 nodeName(k, node) + ": no element holds it and its " + free +
                     " are not fixed (expected it connected or fixed: its "
                     "stiffness would be singular" +
                     (twin[node] >= 0 ? twinHint(k, node, twin[node]) : "") + ")");
  }

  // Rigid translations nothing holds (rigid_translations.hpp), named by the group's lines.
  std::vector<int> root(count, -1), size(count, 0);
  for (int node = 0; node < count; ++node)
    if (held[node]) ++size[root[node] = parts.root(node)];
  // A node of a group at the point of a node outside it hints at the cause.
  std::vector<int> astray(count, -1);
  for (int node = 0; node < count; ++node) {
    const int t = twin[node];
    if (held[node] && t >= 0 && (!held[t] || parts.root(t) != parts.root(node)) &&
        astray[parts.root(node)] < 0)
      astray[parts.root(node)] = node;
  }
  for (const UnrestrainedGroup& g : unrestrainedGroups(k, root)) {
    const int r = g.root;
    std::string free;
    for (int d = 0; d < 3; ++d)
      if (g.free & (1 << d)) free += (free.empty() ? "" : ", ") + std::string(kAxis[d]);
    const std::string hint = astray[r] >= 0 ? twinHint(k, astray[r], twin[astray[r]]) : "";
    const GroupName name = groupName(k, parts, r, size[r]);
    std::string got = "no support fixing " + free + " on any of its nodes";
    if (g.step >= 0 && g.released) {
      const StepSpec& step = k.c.steps[g.step];
      got += " from " + stepName(step) + " (line " + std::to_string(step.where.line) +
             ") on, whose release: lets the last of them go";
    }
    got += ", nor a spring or element joining it to one";
    if (!g.held_other.empty()) got += "; " + g.held_other;
    if (g.step < 0) {
      k.diag.warning(name.line, name.text + " " + name.is + " free to move in " + free +
                                    " as a rigid body in the dynamic steps, where only its "
                                    "inertia resists it (got " +
                                    got +
                                    "; expected, unless it is meant to drift or sink, an "
                                    "anchor, a fairlead or another support fixing " +
                                    free + " on one of its nodes" + hint + ")");
      continue;
    }
    k.diag.error(name.line, name.text + " " + name.is + " free to move in " + free +
                                " as a rigid body: nothing holds it there (got " + got +
                                "; expected an anchor, a fairlead or another support fixing " +
                                free + " on one of its nodes" + hint + ")");
  }

  // Coincident nodes that leave no mechanism: the model runs, but they were perhaps meant as one.
  int reported = 0, more = 0;
  for (int node = 0; node < count; ++node) {
    if (twin[node] < node) continue;  // each pair once, from its first node
    if (reported == kMaxReported) {
      ++more;
      continue;
    }
    ++reported;
    k.diag.warning(k.origins.node_lines[node],
                   nodeName(k, node) + " and " + nodeName(k, twin[node]) + " (line " +
                       std::to_string(k.origins.node_lines[twin[node]]) +
                       ") are at one point and no element joins them: did you mean them merged "
                       "into one node?");
  }
  if (more > 0)
    k.diag.warning(0, "and " + std::to_string(more) + " more pairs of nodes at one point");
}

// Mass of each dof of the model (the diagonal of its consistent mass matrix, Eq. 4.40, 4.49).
std::vector<double> dofMass(const CheckedModel& k, std::set<std::string>& massless_sections) {
  std::vector<double> mass(3 * k.model().nodeCount(), 0.0);
  const model::State state = k.model().initialState();
  Eigen::MatrixXd M;
  for (int e = 0; e < k.model().elementCount(); ++e) {
    const element::Element& element = k.model().element(e);
    element.mass({k.model().reference(), state, e}, element::MassKind::Consistent, M);
    const std::vector<int>& nodes = element.nodes();
    for (size_t I = 0; I < nodes.size(); ++I)
      for (int d = 0; d < 3; ++d) mass[3 * nodes[I] + d] += M(3 * I + d, 3 * I + d);
    if (!(M.diagonal().sum() > 0.0) && !k.origins.elements[e].section.empty())
      massless_sections.insert(k.origins.elements[e].section);
  }
  return mass;
}

void checkMass(const CheckedModel& k, const StepSpec& step, const std::vector<double>& mass,
               const std::set<std::string>& massless_sections) {
  int missing = 0, first = -1;
  for (int node = 0; node < k.model().nodeCount(); ++node)
    for (int d = 0; d < 3; ++d)
      if (!k.model().isConstrained(node, d) && !(mass[3 * node + d] > 0.0)) {
        ++missing;
        if (first < 0) first = node;
      }
  if (missing == 0) return;
  std::string sections;
  for (const std::string& s : massless_sections) sections += (sections.empty() ? "" : ", ") + s;
  k.diag.error(step.where.line,
               stepName(step) + ": needs a mass on every free dof, and " + std::to_string(missing) +
                   " have none, the first at " + nodeName(k, first) + " (line " +
                   std::to_string(k.origins.node_lines[first]) + ") (got " +
                   (sections.empty() ? std::string("only massless elements there")
                                     : "no density: on section " + sections) +
                   ", expected a density: on the sections, or a point_mass on those nodes)");
}

// A period that drives the model, named for the warnings ("history 'shake'", "wave 1 (line 17)").
struct Forcing {
  double period;
  std::string name;
};

// The name of a history, for the warnings.
std::string historyName(const CheckedModel& k, const model::TimeFunction* f) {
  for (const auto& [name, h] : k.histories)
    if (h.get() == f) return name;
  return "";
}

// The periodic histories that drive the model (of loads, pressures and prescribed motions) and
// the periods of the waves.
std::vector<Forcing> periodicForcing(const CheckedModel& k) {
  const model::Model& m = k.model();
  std::set<const model::TimeFunction*> used;
  for (const model::NodalLoad& load : m.nodalLoads()) used.insert(load.history.get());
  for (const model::PressureLoad& p : m.pressures()) used.insert(p.history.get());
  for (int node = 0; node < m.nodeCount(); ++node)
    for (int k = 0; k < 3; ++k) used.insert(m.motion(node, k));
  std::vector<Forcing> periodic;
  for (const model::TimeFunction* f : used)
    if (f && f->period() > 0.0)
      periodic.push_back({f->period(), "history '" + historyName(k, f) + "'"});
  for (size_t i = 0; i < k.ocean.waves.size(); ++i)
    periodic.push_back({k.ocean.waves[i].period, "wave " + std::to_string(i + 1) + " (line " +
                                                     std::to_string(k.ocean.waves[i].line) + ")"});
  // An irregular sea's shortest component: the top of a spectrum's band, a record's cutoff or
  // its Nyquist frequency.
  const double two_pi = 2.0 * std::acos(-1.0);
  if (const auto& s = k.ocean.spectral)
    periodic.push_back({two_pi / (s->options.omega_max_ratio * s->spectrum.peakFrequency()),
                        "the sea's shortest component (the top of waves.band, line " +
                            std::to_string(s->line) + ")"});
  if (const auto& m = k.ocean.measured)
    periodic.push_back(
        {two_pi / std::min(m->omega_cutoff, std::acos(-1.0) / m->record.dt),
         "the record's shortest component (waves.measured, line " + std::to_string(m->line) + ")"});
  return periodic;
}

// Adaptive steps: dt_max, when the case gives none, a tenth of the shortest period that drives
// the model (the local error of a step that strides over a forcing period need not show it).
void boundAdaptiveSteps(StepSpec& step, const std::vector<Forcing>& periodic) {
  solve::AdaptiveSteps& a = *step.dynamic.adaptive;
  if (a.dt_max > 0.0) return;
  for (const Forcing& f : periodic) {
    const double bound = f.period / kStepsPerPeriod;
    if (a.dt_max == 0.0 || bound < a.dt_max) a.dt_max = bound;
  }
}

void checkTimeStep(const CheckedModel& k, const StepSpec& step,
                   const std::vector<Forcing>& periodic) {
  double dt = step.adaptive() ? step.dynamic.adaptive->dt_max : 0.0;
  for (const solve::TimeSegment& s : step.dynamic.schedule) dt = std::max(dt, s.dt);
  const std::string time = unitNames(k.c.units).time;
  for (const Forcing& f : periodic) {
    const double ratio = dt / f.period;
    if (ratio * kStepsPerPeriod <= 1.0) continue;
    k.diag.warning(step.where.line,
                   stepName(step) + ": dt = " + formatNumber(dt) + " " + time + " is " +
                       formatNumber(ratio) + " times the period " + formatNumber(f.period) + " " +
                       time + " of " + f.name + " (dt / period = " + formatNumber(ratio) +
                       "; fewer than " + formatNumber(kStepsPerPeriod) +
                       " steps a period do not resolve it, expected dt <= " +
                       formatNumber(f.period / kStepsPerPeriod) + " " + time + ")");
  }
}

void checkSteps(const CheckedModel& k) {
  const bool needs_mass = std::any_of(k.c.steps.begin(), k.c.steps.end(), [](const StepSpec& s) {
    return s.kind == StepSpec::Kind::Modes || s.kind == StepSpec::Kind::Dynamic;
  });
  std::set<std::string> massless_sections;
  const std::vector<double> mass =
      needs_mass ? dofMass(k, massless_sections) : std::vector<double>();
  const std::vector<Forcing> periodic = periodicForcing(k);
  for (StepSpec& step : k.c.steps) {
    if (step.kind == StepSpec::Kind::Modes || step.kind == StepSpec::Kind::Dynamic)
      checkMass(k, step, mass, massless_sections);
    if (step.kind == StepSpec::Kind::Modes && step.modes.modes > k.model().equationCount())
      k.diag.error(step.where.line, stepName(step) + ": more modes than free dofs (got count: " +
                                        std::to_string(step.modes.modes) + ", expected at most " +
                                        std::to_string(k.model().equationCount()) + ")");
    if (step.kind == StepSpec::Kind::Dynamic) checkTimeStep(k, step, periodic);
    if (step.adaptive()) boundAdaptiveSteps(step, periodic);
  }
}

// "below the seabed (got z = -105 m, expected z >= -100 m, the bed's height at x = 3 m, y = 0 m)"
std::string belowTheBed(const CheckedModel& k, const Eigen::Vector3d& x, double bed) {
  const std::string unit = " " + unitNames(k.c.units).length;
  return "below the seabed (got z = " + formatNumber(x.z()) + unit +
         ", expected z >= " + formatNumber(bed) + unit +
         ", the bed's height at x = " + formatNumber(x.x()) + unit +
         ", y = " + formatNumber(x.y()) + unit + ")";
}

// Nodes and bodies below the bed (more than the position tolerance) at the start; a node that
// carries a body is reported as the body.
void checkSeabed(const CheckedModel& k) {
  const model::NodalField& X = k.model().reference();
  const double tolerance = k.mesh.positionTolerance();
  const auto below = [&](int node) {
    return X(2, node) < k.ocean.bed.height(X(0, node), X(1, node)) - tolerance;
  };
  std::set<int> bodies;
  for (const BodySpec& body : k.ocean.bodies) {
    bodies.insert(body.node);
    if (!below(body.node)) continue;
    const Eigen::Vector3d x = X.col(body.node);
    k.diag.error(body.line, body.where + ": its " + nodeName(k, body.node) + " is " +
                                belowTheBed(k, x, k.ocean.bed.height(x.x(), x.y())));
  }
  int reported = 0, more = 0;
  for (int node = 0; node < k.model().nodeCount(); ++node) {
    if (bodies.count(node) || !below(node)) continue;
    if (reported == kMaxReported) {
      ++more;
      continue;
    }
    ++reported;
    const Eigen::Vector3d x = X.col(node);
    k.diag.error(k.origins.node_lines[node],
                 nodeName(k, node) + ": " + belowTheBed(k, x, k.ocean.bed.height(x.x(), x.y())));
  }
  if (more > 0) k.diag.error(0, "and " + std::to_string(more) + " more nodes below the seabed");
}

// Morison loads and axial damping act on cable elements along their axis; a hoop ring, a membrane,
// a spring or a point mass has none.
void checkLineLoads(const CheckedModel& k) {
  const std::vector<const LineHydroSpec*> morison = k.ocean.elementHydro(k.mesh.elementCount());
  for (int e = 0; e < k.mesh.elementCount(); ++e) {
    const ElementSpec& element = k.mesh.elements[e];
    if (element.kind == ElementSpec::Kind::Cable) continue;
    const bool hoop = element.kind == ElementSpec::Kind::HoopCable;
    const bool damped = hoop && (element.cable_section.axial_damping > 0.0 ||
                                 element.cable_section.damping_ratio > 0.0);
    if (!morison[e] && !damped) continue;
    const ElementOrigin& origin = k.origins.elements[e];
    const std::string on =
        " on " + (hoop ? std::string("a hoop ring") : "a " + k.model().element(e).typeName());
    // "Morison loads act on lines only (got section 'wire' with hydro: on a hoop ring, ...)"
    const auto report = [&](const std::string& what, const char* act, const std::string& key) {
      const std::string got =
          origin.section.empty() ? what : "section '" + origin.section + "' with " + key;
      const std::string expected =
          origin.section.empty() ? what + " on cables only" : "a section without " + key;
      k.diag.error(origin.line, elementName(k, e) + ": " + what + " " + act +
                                    " on lines only (got " + got + on + ", expected " + expected +
                                    ")");
    };
    if (morison[e]) report("Morison loads", "act", "hydro:");
    if (damped) report("axial damping", "acts", "damping:");
  }
}

}  // namespace

ModelOrigins ModelOrigins::sourceless(int nodes, int elements) {
  ModelOrigins origins;
  origins.node_lines.assign(nodes, 0);
  for (int e = 0; e < elements; ++e)
    origins.elements.push_back({0, "mesh.elements[" + std::to_string(e) + "]", ""});
  return origins;
}

void checkModel(const CheckedModel& k) {
  checkGeometry(k);
  checkMechanisms(k);
  checkSteps(k);
  if (k.ocean.has_water) checkSeabed(k);
  checkLineLoads(k);
}

}  // namespace flexmoor::app
