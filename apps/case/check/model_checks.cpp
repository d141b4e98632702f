// The checks of a case's built model and steps (checkModel, case_builder.hpp): what would make a
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
//   ocean      no node and no body below the seabed; hydro: sections on lines only.
#include <algorithm>
#include <numeric>
#include <set>

#include "apps/case/build/node_index.hpp"
#include "apps/case/case_builder.hpp"
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

std::string nodeName(const CaseBuilder& b, int node) {
  return "node " + std::to_string(b.c.node_ids[node]);
}

std::string elementName(const CaseBuilder& b, int e) {
  return "element " + std::to_string(e + 1) + " (" + b.model.element(e).typeName() + " of " +
         b.element_origin[e].where + ")";
}

std::string stepName(const StepSpec& step) { return "step '" + step.name + "'"; }

bool isLine(const element::Element& e) {
  return e.typeName().rfind("cable", 0) == 0 || e.typeName().rfind("axisymmetric", 0) == 0;
}

void checkGeometry(CaseBuilder& b) {
  for (int e = 0; e < b.model.elementCount(); ++e) {
    const element::Element& element = b.model.element(e);
    const double J = element.minRelativeJacobian(b.model.reference());
    if (J > kCollapsed) continue;
    const bool axisymmetric = element.typeName().rfind("axisymmetric", 0) == 0;
    const std::string hint =
        isLine(element) ? std::string("are its middle nodes strictly between its ends, in order") +
                              (axisymmetric ? ", and its points at x > 0 (the radius)?" : "?")
                        : "are its nodes in order around it, and not on one line?";
    b.diag.error(b.element_origin[e].line,
                 elementName(b, e) + ": " +
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
std::vector<int> unjoinedTwins(const CaseBuilder& b,
                               const std::vector<std::vector<int>>& adjacent) {
  const model::NodalField& X = b.model.reference();
  std::vector<int> twin(X.cols(), -1);
  if (X.cols() == 0) return twin;
  const double tolerance = positionTolerance(b);
  if (!(tolerance > 0.0)) return twin;
  const NodeIndex index(X, tolerance);
  const auto joined = [&](int a, int c) {
    for (int e : adjacent[a])
      for (int n : b.model.element(e).nodes())
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

std::string twinHint(const CaseBuilder& b, int node, int twin) {
  return "; " + nodeName(b, node) + " is at the same point as " + nodeName(b, twin) + " (line " +
         std::to_string(b.node_line[twin]) +
         "), which no element joins to it: did you mean them merged into one node?";
}

// The named lines and surfaces a group of nodes (by its root) holds, for the messages.
std::string namesOf(CaseBuilder& b, Components& parts, int root) {
  std::string names;
  const auto add = [&](const char* what, const std::map<std::string, std::vector<int>>& sets) {
    for (const auto& [name, nodes] : sets)
      if (!nodes.empty() && parts.root(nodes.front()) == root)
        names += (names.empty() ? "" : ", ") + std::string(what) + " '" + name + "'";
  };
  add("line", b.c.lines);
  add("surface", b.surfaces);
  return names;
}

// How the messages name a group of joined nodes, and the line of the file that defines it: its
// first named line (in the file's order), else its surface, else its smallest node.
struct GroupName {
  std::string text;
  int line;
  std::string is;  // "is" or "are"
};

GroupName groupName(CaseBuilder& b, Components& parts, int root, int size) {
  const std::string names = namesOf(b, parts, root);
  const std::string nodes = std::to_string(size) + " nodes";
  if (names.empty())
    return {nodeName(b, root) + " and the " +
                (size == 2 ? std::string("node") : std::to_string(size - 1) + " nodes") +
                " joined to it by elements",
            b.node_line[root], "are"};
  int line = b.node_line[root];
  for (const std::string& name : b.line_order) {
    const auto nodes_of = b.c.lines.find(name);
    if (nodes_of != b.c.lines.end() && !nodes_of->second.empty() &&
        parts.root(nodes_of->second.front()) == root) {
      line = b.node_line[nodes_of->second.front()];
      break;
    }
  }
  const bool one = names.find(", ") == std::string::npos;
  return {(one ? names : "the group of " + names) + " (" + nodes + ")", line, "is"};
}

void checkMechanisms(CaseBuilder& b) {
  const int count = b.model.nodeCount();
  std::vector<std::vector<int>> adjacent(count);  // elements at each node
  Components parts(count);
  std::vector<bool> held(count, false);
  for (int e = 0; e < b.model.elementCount(); ++e) {
    const element::Element& element = b.model.element(e);
    if (element.typeName() == "point_mass") continue;
    for (int n : element.nodes()) {
      adjacent[n].push_back(e);
      held[n] = true;
      parts.join(element.nodes().front(), n);
    }
  }
  const std::vector<int> twin = unjoinedTwins(b, adjacent);

  // Free dofs of nodes that no element holds.
  for (int node = 0; node < count; ++node) {
    std::string free;
    for (int k = 0; k < 3; ++k)
      if (!b.model.isConstrained(node, k))
        free += (free.empty() ? "" : ", ") + std::string(kAxis[k]);
    if (held[node] || free.empty()) continue;
    b.diag.error(b.node_line[node], nodeName(b, node) + ": no element holds it and its " + free +
                                        " are not fixed (expected it connected or fixed: its "
                                        "stiffness would be singular" +
                                        (twin[node] >= 0 ? twinHint(b, node, twin[node]) : "") +
                                        ")");
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
  for (const UnrestrainedGroup& g : unrestrainedGroups(b, root)) {
    const int r = g.root;
    std::string free;
    for (int k = 0; k < 3; ++k)
      if (g.free & (1 << k)) free += (free.empty() ? "" : ", ") + std::string(kAxis[k]);
    const std::string hint = astray[r] >= 0 ? twinHint(b, astray[r], twin[astray[r]]) : "";
    const GroupName name = groupName(b, parts, r, size[r]);
    std::string got = "no support fixing " + free + " on any of its nodes";
    if (g.step >= 0 && g.released) {
      const StepSpec& step = b.c.steps[g.step];
      got += " from " + stepName(step) + " (line " + std::to_string(step.where.line) +
             ") on, whose release: lets the last of them go";
    }
    got += ", nor a spring or element joining it to one";
    if (!g.held_other.empty()) got += "; " + g.held_other;
    if (g.step < 0) {
      b.diag.warning(name.line, name.text + " " + name.is + " free to move in " + free +
                                    " as a rigid body in the dynamic steps, where only its "
                                    "inertia resists it (got " +
                                    got +
                                    "; expected, unless it is meant to drift or sink, an "
                                    "anchor, a fairlead or another support fixing " +
                                    free + " on one of its nodes" + hint + ")");
      continue;
    }
    b.diag.error(name.line, name.text + " " + name.is + " free to move in " + free +
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
    b.diag.warning(b.node_line[node],
                   nodeName(b, node) + " and " + nodeName(b, twin[node]) + " (line " +
                       std::to_string(b.node_line[twin[node]]) +
                       ") are at one point and no element joins them: did you mean them merged "
                       "into one node?");
  }
  if (more > 0)
    b.diag.warning(0, "and " + std::to_string(more) + " more pairs of nodes at one point");
}

// Mass of each dof of the model (the diagonal of its consistent mass matrix, Eq. 4.40, 4.49).
std::vector<double> dofMass(const CaseBuilder& b, std::set<std::string>& massless_sections) {
  std::vector<double> mass(3 * b.model.nodeCount(), 0.0);
  const model::State state = b.model.initialState();
  Eigen::MatrixXd M;
  for (int e = 0; e < b.model.elementCount(); ++e) {
    const element::Element& element = b.model.element(e);
    element.mass({b.model.reference(), state, e}, element::MassKind::Consistent, M);
    const std::vector<int>& nodes = element.nodes();
    for (size_t I = 0; I < nodes.size(); ++I)
      for (int k = 0; k < 3; ++k) mass[3 * nodes[I] + k] += M(3 * I + k, 3 * I + k);
    if (!(M.diagonal().sum() > 0.0) && !b.element_origin[e].section.empty())
      massless_sections.insert(b.element_origin[e].section);
  }
  return mass;
}

void checkMass(CaseBuilder& b, const StepSpec& step, const std::vector<double>& mass,
               const std::set<std::string>& massless_sections) {
  int missing = 0, first = -1;
  for (int node = 0; node < b.model.nodeCount(); ++node)
    for (int k = 0; k < 3; ++k)
      if (!b.model.isConstrained(node, k) && !(mass[3 * node + k] > 0.0)) {
        ++missing;
        if (first < 0) first = node;
      }
  if (missing == 0) return;
  std::string sections;
  for (const std::string& s : massless_sections) sections += (sections.empty() ? "" : ", ") + s;
  b.diag.error(step.where.line,
               stepName(step) + ": needs a mass on every free dof, and " + std::to_string(missing) +
                   " have none, the first at " + nodeName(b, first) + " (line " +
                   std::to_string(b.node_line[first]) + ") (got " +
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
std::string historyName(const CaseBuilder& b, const model::TimeFunction* f) {
  for (const auto& [name, h] : b.histories)
    if (h.get() == f) return name;
  return "";
}

// The periodic histories that drive the model (of loads, pressures and prescribed motions) and
// the periods of the waves.
std::vector<Forcing> periodicForcing(const CaseBuilder& b) {
  const model::Model& m = b.model;
  std::set<const model::TimeFunction*> used;
  for (const model::NodalLoad& load : m.nodalLoads()) used.insert(load.history.get());
  for (const model::PressureLoad& p : m.pressures()) used.insert(p.history.get());
  for (int node = 0; node < m.nodeCount(); ++node)
    for (int k = 0; k < 3; ++k) used.insert(m.motion(node, k));
  std::vector<Forcing> periodic;
  for (const model::TimeFunction* f : used)
    if (f && f->period() > 0.0)
      periodic.push_back({f->period(), "history '" + historyName(b, f) + "'"});
  for (size_t i = 0; i < b.hydro.waves.size(); ++i)
    periodic.push_back({b.hydro.waves[i].period, "wave " + std::to_string(i + 1) + " (line " +
                                                     std::to_string(b.hydro.waves[i].line) + ")"});
  // An irregular sea's shortest component: the top of a spectrum's band, a record's cutoff or
  // its Nyquist frequency.
  const double two_pi = 2.0 * std::acos(-1.0);
  if (const auto& s = b.hydro.spectral)
    periodic.push_back({two_pi / (s->options.omega_max_ratio * s->spectrum.peakFrequency()),
                        "the sea's shortest component (the top of waves.band, line " +
                            std::to_string(s->line) + ")"});
  if (const auto& m = b.hydro.measured)
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

void checkTimeStep(CaseBuilder& b, const StepSpec& step, const std::vector<Forcing>& periodic) {
  double dt = step.adaptive() ? step.dynamic.adaptive->dt_max : 0.0;
  for (const solve::TimeSegment& s : step.dynamic.schedule) dt = std::max(dt, s.dt);
  const std::string time = unitNames(b.c.units).time;
  for (const Forcing& f : periodic) {
    const double ratio = dt / f.period;
    if (ratio * kStepsPerPeriod <= 1.0) continue;
    b.diag.warning(step.where.line,
                   stepName(step) + ": dt = " + formatNumber(dt) + " " + time + " is " +
                       formatNumber(ratio) + " times the period " + formatNumber(f.period) + " " +
                       time + " of " + f.name + " (dt / period = " + formatNumber(ratio) +
                       "; fewer than " + formatNumber(kStepsPerPeriod) +
                       " steps a period do not resolve it, expected dt <= " +
                       formatNumber(f.period / kStepsPerPeriod) + " " + time + ")");
  }
}

void checkSteps(CaseBuilder& b) {
  const bool needs_mass = std::any_of(b.c.steps.begin(), b.c.steps.end(), [](const StepSpec& s) {
    return s.kind == StepSpec::Kind::Modes || s.kind == StepSpec::Kind::Dynamic;
  });
  std::set<std::string> massless_sections;
  const std::vector<double> mass =
      needs_mass ? dofMass(b, massless_sections) : std::vector<double>();
  const std::vector<Forcing> periodic = periodicForcing(b);
  for (StepSpec& step : b.c.steps) {
    if (step.kind == StepSpec::Kind::Modes || step.kind == StepSpec::Kind::Dynamic)
      checkMass(b, step, mass, massless_sections);
    if (step.kind == StepSpec::Kind::Modes && step.modes.modes > b.model.equationCount())
      b.diag.error(step.where.line, stepName(step) + ": more modes than free dofs (got count: " +
                                        std::to_string(step.modes.modes) + ", expected at most " +
                                        std::to_string(b.model.equationCount()) + ")");
    if (step.kind == StepSpec::Kind::Dynamic) checkTimeStep(b, step, periodic);
    if (step.adaptive()) boundAdaptiveSteps(step, periodic);
  }
}

// "below the seabed (got z = -105 m, expected z >= -100 m, the bed's height at x = 3 m, y = 0 m)"
std::string belowTheBed(const CaseBuilder& b, const Eigen::Vector3d& x, double bed) {
  const std::string unit = " " + unitNames(b.c.units).length;
  return "below the seabed (got z = " + formatNumber(x.z()) + unit +
         ", expected z >= " + formatNumber(bed) + unit +
         ", the bed's height at x = " + formatNumber(x.x()) + unit +
         ", y = " + formatNumber(x.y()) + unit + ")";
}

// Nodes and bodies below the bed (more than the position tolerance) at the start; a node that
// carries a body is reported as the body.
void checkSeabed(CaseBuilder& b) {
  const model::NodalField& X = b.model.reference();
  const double tolerance = positionTolerance(b);
  const auto below = [&](int node) {
    return X(2, node) < b.hydro.bed.height(X(0, node), X(1, node)) - tolerance;
  };
  std::set<int> bodies;
  for (const BodySpec& body : b.hydro.bodies) {
    bodies.insert(body.node);
    if (!below(body.node)) continue;
    const Eigen::Vector3d x = X.col(body.node);
    b.diag.error(body.line, body.where + ": its " + nodeName(b, body.node) + " is " +
                                belowTheBed(b, x, b.hydro.bed.height(x.x(), x.y())));
  }
  int reported = 0, more = 0;
  for (int node = 0; node < b.model.nodeCount(); ++node) {
    if (bodies.count(node) || !below(node)) continue;
    if (reported == kMaxReported) {
      ++more;
      continue;
    }
    ++reported;
    const Eigen::Vector3d x = X.col(node);
    b.diag.error(b.node_line[node],
                 nodeName(b, node) + ": " + belowTheBed(b, x, b.hydro.bed.height(x.x(), x.y())));
  }
  if (more > 0) b.diag.error(0, "and " + std::to_string(more) + " more nodes below the seabed");
}

// Morison loads and axial damping act on cable elements along their axis; a hoop ring has none.
void checkHydroSections(CaseBuilder& b) {
  for (int e = 0; e < b.model.elementCount(); ++e) {
    const std::string& section = b.element_origin[e].section;
    if (b.element_types[e] != "hoop_cable" || section.empty() || !b.sections.at(section)) continue;
    const SectionSpec& spec = *b.sections.at(section);
    if (spec.hydro)
      b.diag.error(b.element_origin[e].line,
                   elementName(b, e) + ": Morison loads act on lines only (got section '" +
                       section +
                       "' with hydro: on a hoop ring, expected a section without hydro:)");
    if (spec.section.axial_damping > 0.0 || spec.section.damping_ratio > 0.0)
      b.diag.error(b.element_origin[e].line,
                   elementName(b, e) + ": axial damping acts on lines only (got section '" +
                       section +
                       "' with damping: on a hoop ring, expected a section without damping:)");
  }
}

}  // namespace

void checkModel(CaseBuilder& b) {
  checkGeometry(b);
  checkMechanisms(b);
  checkSteps(b);
  if (b.hydro.has_water) checkSeabed(b);
  checkHydroSections(b);
}

}  // namespace flexmoor::app
