// steps: of a case file, in order; each is `relax: {...}`, `static: {...}`, `modes: {...}` or
// `dynamic: {...}` and maps onto solve::RelaxationOptions, solve::StaticOptions,
// solve::ModalOptions or solve::DynamicOptions.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "apps/case/case_builder.hpp"
#include "apps/case/read/read_time_span.hpp"

namespace flexmoor::app {
namespace {

using solve::NewtonFlavour;

// omega^2 (what ModalOptions::shift holds) and omega, for the shift of a frequency analysis.
constexpr QuantityKind kOmegaSquared{"a squared angular frequency (1/s^2)", {0, 0, -2}};
constexpr QuantityKind kOmega{"an angular frequency (rad/s)", {0, 0, -1}};
// Rayleigh damping C = a_M M + a_K K: a_M in 1/s, a_K in s.
constexpr QuantityKind kPerTime{"a rate (1/s)", {0, 0, -1}};

const std::vector<std::pair<std::string, element::MassKind>>& massChoices() {
  static const std::vector<std::pair<std::string, element::MassKind>> choices = {
      {"consistent", element::MassKind::Consistent}, {"lumped", element::MassKind::Lumped}};
  return choices;
}

std::optional<bool> readBool(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  return b.in.choice<bool>(n, path, {{"true", true}, {"false", false}});
}

// A plain number in [low, high], with the range in the message.
std::optional<double> numberIn(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                               double low, double high, const std::string& range) {
  const auto value = b.in.quantity(n, path, kind::kNumber);
  if (!value) return std::nullopt;
  if (*value >= low && *value <= high) return value;
  b.diag.error(n, path + ": out of range (got " + n.Scalar() + ", expected " + range + ")");
  return std::nullopt;
}

// newton: one of `choices` (dynamic steps have no BFGS).
void readFlavour(CaseBuilder& b, Fields& f, NewtonFlavour& flavour, bool with_bfgs) {
  const YAML::Node* n = f.find("newton");
  if (!n) return;
  std::vector<std::pair<std::string, NewtonFlavour>> choices = {
      {"full", NewtonFlavour::Full}, {"modified", NewtonFlavour::Modified}};
  if (with_bfgs) choices.emplace_back("bfgs", NewtonFlavour::Bfgs);
  choices.emplace_back("self_corrective", NewtonFlavour::SelfCorrective);  // Eq. 4.20
  flavour = b.in.choice(*n, f.path("newton"), choices).value_or(flavour);
}

// Newton iterations and their convergence test (Eq. 5.1 and/or the residual); shared by static
// and dynamic steps.
void readNewton(CaseBuilder& b, Fields& f, int& stiffness_update, int& max_iterations,
                solve::Convergence& c) {
  Input& in = b.in;
  stiffness_update = in.integerOr(f, "stiffness_update", 1, stiffness_update);
  max_iterations = in.integerOr(f, "max_iterations", 1, max_iterations);
  c.displacement_tolerance = in.quantityOr(f, "tolerance", kind::kNumber, Limit::Positive,
                                           c.displacement_tolerance);  // Eq. 5.1
  c.residual_tolerance =
      in.quantityOr(f, "residual_tolerance", kind::kNumber, Limit::Positive, c.residual_tolerance);
  if (const YAML::Node* n = f.find("criterion")) {
    using Uses = std::pair<bool, bool>;  // displacement, residual
    const auto uses = in.choice<Uses>(
        *n, f.path("criterion"),
        {{"displacement", {true, false}}, {"residual", {false, true}}, {"both", {true, true}}});
    if (uses) std::tie(c.use_displacement, c.use_residual) = *uses;
  }
}

// `waves: still | frozen` of a static or relax step: whether its loads see still water (the
// default) or the waves frozen as they stand at the step's time.
void readWaves(CaseBuilder& b, Fields& f, bool& frozen) {
  if (const YAML::Node* n = f.find("waves"))
    frozen = b.in.choice<bool>(*n, f.path("waves"), {{"still", false}, {"frozen", true}})
                 .value_or(frozen);
}

// Viscous relaxation, Appendix C.
void readRelax(CaseBuilder& b, Fields& f, solve::RelaxationOptions& o) {
  Input& in = b.in;
  readWaves(b, f, o.frozen_waves);
  o.load_factor = in.quantityOr(f, "load_factor", kind::kNumber, Limit::Any, o.load_factor);
  o.tolerance = in.quantityOr(f, "tolerance", kind::kNumber, Limit::Positive, o.tolerance);  // C.15
  // C of Eq. C.11 multiplies a displacement over one unit of pseudo-time: a force per length.
  o.damping = in.quantityOr(f, "damping", kind::kStiffness, Limit::Positive, o.damping);
  o.initial_damping_factor = in.quantityOr(f, "initial_damping_factor", kind::kNumber,
                                           Limit::Positive, o.initial_damping_factor);       // C.13
  o.decrement = in.quantityOr(f, "decrement", kind::kNumber, Limit::Positive, o.decrement);  // C.14
  o.residual_tolerance =
      in.quantityOr(f, "residual_tolerance", kind::kNumber, Limit::Positive, o.residual_tolerance);
  o.max_steps = in.integerOr(f, "max_steps", 1, o.max_steps);
  o.max_iterations = in.integerOr(f, "max_iterations", 1, o.max_iterations);
}

// Incremental Newton, modified Newton or BFGS, under load or arc-length control.
void readStatic(CaseBuilder& b, Fields& f, solve::StaticOptions& o) {
  Input& in = b.in;
  readWaves(b, f, o.frozen_waves);
  o.load_factor = in.quantityOr(f, "load_factor", kind::kNumber, Limit::Any, o.load_factor);
  o.increments = in.integerOr(f, "increments", 1, o.increments);
  if (const YAML::Node* n = f.find("control"))
    o.control = in.choice(*n, f.path("control"),
                          std::vector<std::pair<std::string, solve::LoadControl>>{
                              {"load", solve::LoadControl::Load},
                              {"arc_length", solve::LoadControl::ArcLength}})
                    .value_or(o.control);
  // Arc-length keys mean nothing under load control: refuse them rather than ignore them.
  const bool arc = peekText(f.node(), "control") == "arc_length";
  for (const char* key : {"psi", "desired_iterations", "max_increments"})
    if (f.find(key) && !arc)
      b.diag.error(*f.find(key),
                   f.path(key) + ": only used with control: arc_length (got " +
                       (f.find("control") ? "control: " + peekText(f.node(), "control")
                                          : std::string("no control: key")) +
                       ")");
  if (const YAML::Node* n = f.find("psi"))  // 0 cylindrical .. 1 spherical
    o.arc.psi = numberIn(b, *n, f.path("psi"), 0.0, 1.0, "0 to 1").value_or(o.arc.psi);
  o.arc.desired_iterations = in.integerOr(f, "desired_iterations", 1, o.arc.desired_iterations);
  o.arc.max_increments = in.integerOr(f, "max_increments", 1, o.arc.max_increments);
  readFlavour(b, f, o.flavour, true);
  if (arc && f.find("newton") && o.flavour != NewtonFlavour::Full)
    b.diag.error(*f.find("newton"), f.path("newton") +
                                        ": arc length iterates with full Newton "
                                        "(got " +
                                        peekText(f.node(), "newton") +
                                        ", expected full or no newton: key)");
  readNewton(b, f, o.stiffness_update, o.max_iterations, o.convergence);
  if (const YAML::Node* n = f.find("pressure_stiffness"))
    o.pressure_load_stiffness =
        readBool(b, *n, f.path("pressure_stiffness")).value_or(o.pressure_load_stiffness);
}

// The shift sigma of K - sigma M: a plain number or 1/s^2 is omega^2 as ModalOptions holds it;
// rad/s (or Hz, a cyclic frequency) is an omega and is squared, keeping its sign.
std::optional<double> readShift(CaseBuilder& b, const YAML::Node& n, const std::string& path) {
  if (!n.IsScalar()) {
    b.diag.error(n, path + ": expected " + kOmegaSquared.name + " or " + kOmega.name + " (got " +
                        describeNode(n) + ")");
    return std::nullopt;
  }
  try {
    return parseValue(n.Scalar(), kOmegaSquared, b.in.units);
  } catch (const UnitError&) {
  }
  try {
    double omega = parseValue(n.Scalar(), kOmega, b.in.units);
    if (n.Scalar().find("Hz") != std::string::npos) omega *= 2.0 * M_PI;
    return std::copysign(omega * omega, omega);
  } catch (const UnitError&) {
  }
  b.diag.error(n, path + ": expected " + kOmegaSquared.name + " or " + kOmega.name + " (got " +
                      describeNode(n) + ")");
  return std::nullopt;
}

// Lowest modes about the current state, Chapter IV.
void readModes(CaseBuilder& b, Fields& f, solve::ModalOptions& o) {
  o.modes = b.in.integerOr(f, "count", 1, o.modes);
  if (const YAML::Node* n = f.find("shift"))
    o.shift = readShift(b, *n, f.path("shift")).value_or(o.shift);
  if (const YAML::Node* n = f.find("mass"))
    o.mass = b.in.choice(*n, f.path("mass"), massChoices()).value_or(o.mass);
  o.tolerance = b.in.quantityOr(f, "tolerance", kind::kNumber, Limit::Positive, o.tolerance);
}

// True when an earlier step of the case sets a load factor (relax, static and dynamic steps do;
// modes steps do not).
bool loadFactorSetBefore(const CaseBuilder& b) {
  return std::any_of(b.c.steps.begin(), b.c.steps.end(),
                     [](const StepSpec& s) { return s.kind != StepSpec::Kind::Modes; });
}

// Newmark (Eq. 4.55-4.63), or HHT-alpha, with Newton iterations in every time step.
void readDynamic(CaseBuilder& b, Fields& f, StepSpec& step) {
  Input& in = b.in;
  solve::DynamicOptions& o = step.dynamic;
  readTimeSpan(b, f, step);
  // The load factor held through the step: given, or the one the previous step left; 1 when no
  // earlier step sets one, so that gravity and the loads without a history act.
  if (const YAML::Node* n = f.find("load_factor"))
    o.load_factor = in.quantity(*n, f.path("load_factor"), kind::kNumber);
  else if (!loadFactorSetBefore(b))
    o.load_factor = 1.0;
  const YAML::Node* gamma = f.find("gamma");
  const YAML::Node* beta = f.find("beta");
  if (gamma)  // below 1/2 the scheme amplifies: negative numerical damping
    o.gamma = numberIn(b, *gamma, f.path("gamma"), 0.5, 1.0, "0.5 to 1").value_or(o.gamma);
  if (beta)  // beta = 0 is the explicit central difference, which this implicit solver is not
    o.beta = in.quantity(*beta, f.path("beta"), kind::kNumber, Limit::Positive).value_or(o.beta);
  if (const YAML::Node* n = f.find("hht_alpha")) {
    const auto alpha = numberIn(b, *n, f.path("hht_alpha"), -1.0 / 3.0, 0.0, "-1/3 to 0");
    if (alpha) o.hht_alpha = *alpha;
    if (alpha && *alpha != 0.0 && (gamma || beta))
      b.diag.error(*n, f.path("hht_alpha") + ": given with " + (gamma ? "gamma" : "beta") +
                           " (expected one or the other: HHT sets gamma = (1 - 2 alpha) / 2 and "
                           "beta = (1 - alpha)^2 / 4)");
  }
  readFlavour(b, f, o.flavour, false);
  readNewton(b, f, o.stiffness_update, o.max_iterations, o.convergence);
  if (const YAML::Node* n = f.find("mass"))
    o.mass = in.choice(*n, f.path("mass"), massChoices()).value_or(o.mass);
  if (const YAML::Node* n = f.find("rayleigh")) {  // C = a_M M + a_K K_T
    Fields r(b.diag, *n, f.path("rayleigh"), {"mass", "stiffness"});
    o.rayleigh_mass = in.quantityOr(r, "mass", kPerTime, Limit::NonNegative, o.rayleigh_mass);
    o.rayleigh_stiffness =
        in.quantityOr(r, "stiffness", kind::kTime, Limit::NonNegative, o.rayleigh_stiffness);
  }
  if (const YAML::Node* n = f.find("max_step_cuts"))
    o.max_step_cuts = in.integer(*n, f.path("max_step_cuts"), 0).value_or(o.max_step_cuts);
  if (const YAML::Node* n = f.find("pressure_stiffness"))
    o.pressure_load_stiffness =
        readBool(b, *n, f.path("pressure_stiffness")).value_or(o.pressure_load_stiffness);
  using Update = solve::DynamicOptions::LoadMatrixUpdate;
  if (const YAML::Node* n = f.find("load_matrices"))
    o.load_matrices =
        in.choice<Update>(
              *n, f.path("load_matrices"),
              {{"step", Update::Step}, {"iteration", Update::Iteration}, {"off", Update::Off}})
            .value_or(o.load_matrices);
}

// release: [{node: REF, dofs: [x, z]}, ...]: supports let go when the step starts. Each dof must be
// held by a support (or an earlier step's release must not have freed it already).
void readRelease(CaseBuilder& b, Fields& f, StepSpec& step) {
  const YAML::Node* list = f.find("release");
  if (!list) return;
  const std::vector<YAML::Node> items = listItems(b.diag, *list, f.path("release"));
  for (size_t i = 0; i < items.size(); ++i) {
    Fields r(b.diag, items[i], itemPath(f.path("release"), i), {"node", "nodes", "dofs"});
    const auto nodes = nodeOrNodes(b, r);
    const YAML::Node* dofs_node = r.require("dofs");
    const auto dofs = dofs_node ? readFix(b, *dofs_node, r.path("dofs")) : std::nullopt;
    if (!nodes || !dofs) continue;
    for (int node : *nodes)
      for (int k : *dofs) {
        const std::pair<int, int> dof{node, k};
        const bool held = b.conditions.held(node, k) && !b.released.count(dof);
        if (!held) {
          b.diag.error(items[i],
                       r.path() + ": node " + std::to_string(b.c.node_ids[node]) + " " + "xyz"[k] +
                           " is not held by a support at this step (got " +
                           (b.released.count(dof) ? "released by an earlier step" : "a free dof") +
                           ", expected a dof of supports:)");
          continue;
        }
        b.released.insert(dof);
        step.release.push_back(dof);
      }
  }
}

// `name:`, or the kind of step when there is none.
std::string stepName(CaseBuilder& b, const Fields& f, const char* kind) {
  const YAML::Node* n = f.find("name");
  const std::string name = n ? b.in.text(*n, f.path("name")).value_or(kind) : kind;
  if (name.size() > kMaxNameLength)
    b.diag.error(*n, f.path("name") + ": too long for the results (got " +
                         std::to_string(name.size()) + " characters, expected at most " +
                         std::to_string(kMaxNameLength) + ")");
  return name;
}

// The keys each kind of step takes; static and dynamic steps share the Newton keys.
const std::vector<std::string>& keysOf(StepSpec::Kind kind) {
  const auto with = [](std::vector<std::string> own) {
    for (const char* key : {"newton", "stiffness_update", "tolerance", "residual_tolerance",
                            "criterion", "max_iterations"})
      own.push_back(key);
    return own;
  };
  static const std::vector<std::string> relax = {
      "name",      "load_factor",        "tolerance", "damping",        "initial_damping_factor",
      "decrement", "residual_tolerance", "max_steps", "max_iterations", "release",
      "waves"};
  static const std::vector<std::string> statics =
      with({"name", "load_factor", "increments", "control", "psi", "desired_iterations",
            "max_increments", "pressure_stiffness", "release", "waves"});
  static const std::vector<std::string> modes = {"name", "count",     "shift",
                                                 "mass", "tolerance", "release"};
  static const std::vector<std::string> dynamic = [&] {
    std::vector<std::string> keys =
        with({"name", "load_factor", "gamma", "beta", "hht_alpha", "mass", "rayleigh",
              "max_step_cuts", "pressure_stiffness", "load_matrices", "release"});
    keys.insert(keys.end(), timeSpanKeys().begin(), timeSpanKeys().end());
    return keys;
  }();
  switch (kind) {
    case StepSpec::Kind::Relax:
      return relax;
    case StepSpec::Kind::Static:
      return statics;
    case StepSpec::Kind::Modes:
      return modes;
    case StepSpec::Kind::Dynamic:
      return dynamic;
  }
  return relax;
}

const std::vector<std::pair<std::string, StepSpec::Kind>>& stepKinds() {
  static const std::vector<std::pair<std::string, StepSpec::Kind>> kinds = {
      {"relax", StepSpec::Kind::Relax},
      {"static", StepSpec::Kind::Static},
      {"modes", StepSpec::Kind::Modes},
      {"dynamic", StepSpec::Kind::Dynamic}};
  return kinds;
}

// The keys of `map` over `step`'s values; its name `name` unless it gives one.
void readStepKeys(CaseBuilder& b, StepSpec step, const YAML::Node& map, const std::string& path,
                  const std::string& name) {
  Fields f(b.diag, map, path, keysOf(step.kind));
  switch (step.kind) {
    case StepSpec::Kind::Relax:
      readRelax(b, f, step.relax);
      break;
    case StepSpec::Kind::Static:
      readStatic(b, f, step.statics);
      break;
    case StepSpec::Kind::Modes:
      readModes(b, f, step.modes);
      break;
    case StepSpec::Kind::Dynamic:
      readDynamic(b, f, step);
      break;
  }
  readRelease(b, f, step);
  step.name = stepName(b, f, name.c_str());
  b.c.steps.push_back(std::move(step));
}

void readStep(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  const std::vector<MapEntry> entries =
      item.IsMap() ? mapEntries(b.diag, item, path) : std::vector<MapEntry>{};
  const auto& kinds = stepKinds();
  const auto found = entries.size() != 1
                         ? kinds.end()
                         : std::find_if(kinds.begin(), kinds.end(),
                                        [&](const auto& k) { return k.first == entries[0].key; });
  if (found == kinds.end()) {
    const std::string got = !item.IsMap()         ? describeNode(item)
                            : entries.size() == 1 ? "'" + entries[0].key + "'"
                                                  : std::to_string(entries.size()) + " keys";
    b.diag.error(item, path + ": not a step (got " + got +
                           ", expected one of 'relax: {...}', 'static: {...}', 'modes: {...}' or "
                           "'dynamic: {...}')");
    return;
  }
  const MapEntry& e = entries[0];
  StepSpec step;
  step.kind = found->second;
  step.where = {b.diag.file(), lineOf(e.key_node)};
  readStepKeys(b, std::move(step), e.value, childPath(path, e.key), found->first);
}

}  // namespace

void readStepOf(CaseBuilder& b, StepSpec step, const YAML::Node* map, const std::string& path,
                const std::string& name) {
  const YAML::Node keys = map ? *map : YAML::Node(YAML::NodeType::Map);
  step.where = {b.diag.file(), map ? lineOf(*map) : 0};
  readStepKeys(b, std::move(step), keys, path, name);
}

void readSteps(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "steps");
  if (items.empty() && (n.IsNull() || n.IsSequence()))
    b.diag.error(n,
                 "steps: no steps (expected at least one relax:, static:, modes: or dynamic: "
                 "step)");
  for (size_t i = 0; i < items.size(); ++i) readStep(b, items[i], itemPath("steps", i));
}

}  // namespace flexmoor::app
