// steps: of a case file, in order; each is `relax: {...}` or `static: {...}` and maps onto
// solve::RelaxationOptions or solve::StaticOptions.
#include <tuple>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

using solve::NewtonFlavour;

// Viscous relaxation, Appendix C.
void readRelax(CaseBuilder& b, Fields& f, solve::RelaxationOptions& o) {
  Input& in = b.in;
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

// Incremental Newton or modified Newton; convergence by Eq. 5.1 and/or the residual.
void readStatic(CaseBuilder& b, Fields& f, solve::StaticOptions& o) {
  Input& in = b.in;
  o.load_factor = in.quantityOr(f, "load_factor", kind::kNumber, Limit::Any, o.load_factor);
  o.increments = in.integerOr(f, "increments", 1, o.increments);
  if (const YAML::Node* n = f.find("newton"))
    o.flavour = in.choice(*n, f.path("newton"),
                          std::vector<std::pair<std::string, NewtonFlavour>>{
                              {"full", NewtonFlavour::Full}, {"modified", NewtonFlavour::Modified}})
                    .value_or(o.flavour);
  o.stiffness_update = in.integerOr(f, "stiffness_update", 1, o.stiffness_update);
  o.max_iterations = in.integerOr(f, "max_iterations", 1, o.max_iterations);
  solve::Convergence& c = o.convergence;
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

// `name:`, or the kind of step when there is none.
std::string stepName(CaseBuilder& b, const Fields& f, const char* kind) {
  const YAML::Node* n = f.find("name");
  return n ? b.in.text(*n, f.path("name")).value_or(kind) : kind;
}

void readStep(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  const std::vector<MapEntry> entries =
      item.IsMap() ? mapEntries(b.diag, item, path) : std::vector<MapEntry>{};
  if (entries.size() != 1 || (entries[0].key != "relax" && entries[0].key != "static")) {
    const std::string got = !item.IsMap()         ? describeNode(item)
                            : entries.size() == 1 ? "'" + entries[0].key + "'"
                                                  : std::to_string(entries.size()) + " keys";
    b.diag.error(item, path + ": not a step (got " + got +
                           ", expected one of 'relax: {...}' or 'static: {...}')");
    return;
  }
  const MapEntry& e = entries[0];
  StepSpec step;
  step.where = {b.diag.file(), lineOf(e.key_node)};
  const std::string step_path = childPath(path, e.key);
  if (e.key == "relax") {
    Fields f(b.diag, e.value, step_path,
             {"name", "load_factor", "tolerance", "damping", "initial_damping_factor", "decrement",
              "residual_tolerance", "max_steps", "max_iterations"});
    step.kind = StepSpec::Kind::Relax;
    readRelax(b, f, step.relax);
    step.name = stepName(b, f, "relax");
  } else {
    Fields f(b.diag, e.value, step_path,
             {"name", "load_factor", "increments", "newton", "stiffness_update", "tolerance",
              "residual_tolerance", "criterion", "max_iterations"});
    step.kind = StepSpec::Kind::Static;
    readStatic(b, f, step.statics);
    step.name = stepName(b, f, "static");
  }
  b.c.steps.push_back(std::move(step));
}

}  // namespace

void readSteps(CaseBuilder& b, const YAML::Node& n) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, "steps");
  if (items.empty() && (n.IsNull() || n.IsSequence()))
    b.diag.error(n, "steps: no steps (expected at least one relax: or static: step)");
  for (size_t i = 0; i < items.size(); ++i) readStep(b, items[i], itemPath("steps", i));
}

}  // namespace flexmoor::app
