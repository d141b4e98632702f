// summary: of a case file: the named scalars a run reports in summary.json.
#include <algorithm>
#include <charconv>

#include "apps/case/build/line_summary.hpp"
#include "apps/case/case_builder.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

using Quantity = SummarySpec::Quantity;

// What a quantity is measured on: a node, one end of a cable or spring, a membrane element, a mode
// of a modes step, the whole model, a named line, or the run itself (its cost).
enum class Target { Node, ElementEnd, Membrane, Mode, Model, Line, Run };

// The unit a quantity is reported in. A support reaction of an axisymmetric model is per radian
// of circumference, like every force of its meridian (a hoop cable's tension is a whole force).
enum class Measure { Length, Velocity, Force, Reaction, ForcePerLength, AngularFrequency, Time };

struct QuantityInfo {
  Quantity quantity;
  int component;
  Measure measure;
  Target target;
};

// True when the model is an axisymmetric meridian (it has axisymmetric membranes or hoop cables).
bool axisymmetric(const CaseBuilder& b) {
  return std::any_of(b.element_types.begin(), b.element_types.end(), [](const std::string& t) {
    return t == "axisymmetric_membrane" || t == "hoop_cable";
  });
}

std::string unitOf(Measure m, UnitSystem system, bool per_radian) {
  const UnitNames units = unitNames(system);
  switch (m) {
    case Measure::Length:
      return units.length;
    case Measure::Velocity:
      return units.length + "/" + units.time;
    case Measure::Force:
      return units.force;
    case Measure::Reaction:
      return per_radian ? units.force + "/rad" : units.force;
    case Measure::ForcePerLength:
      return units.force + "/" + units.length;
    case Measure::AngularFrequency:
      return "rad/s";
    case Measure::Time:
      return units.time;
  }
  return "";
}

Dimension dimensionOf(Measure m) {
  switch (m) {
    case Measure::Length:
      return kind::kLength.dimension;
    case Measure::Velocity:
      return {0, 1, -1};
    case Measure::Force:
    case Measure::Reaction:
      return kind::kForce.dimension;
    case Measure::ForcePerLength:
      return {1, 0, -2};
    case Measure::AngularFrequency:
      return {0, 0, -1};
    case Measure::Time:
      return kind::kTime.dimension;
  }
  return {};
}

// `unit: in` reports the quantity in that unit (of its dimension) instead of the case system's.
void readReportUnit(CaseBuilder& b, const Fields& f, Measure measure, SummarySpec& s) {
  const YAML::Node* n = f.find("unit");
  if (!n) return;
  const auto text = b.in.text(*n, f.path("unit"));
  if (!text) return;
  const Dimension wanted = dimensionOf(measure);
  try {
    const Unit u = parseUnit(*text);
    if (u.dimension != wanted) {
      b.diag.error(*n, f.path("unit") + ": not a unit of this quantity (got '" + *text + "', " +
                           describeDimension(u.dimension) + ", expected " +
                           describeDimension(wanted) + " like " + s.unit + ")");
      return;
    }
    s.scale *= systemScale(wanted, b.in.units) / u.si_factor;
    s.unit = *text;
  } catch (const UnitError& e) {
    b.diag.error(*n, f.path("unit") + ": " + e.what());
  }
}

const std::vector<std::pair<std::string, QuantityInfo>>& quantities() {
  static const std::vector<std::pair<std::string, QuantityInfo>> table = {
      {"displacement_x", {Quantity::Displacement, 0, Measure::Length, Target::Node}},
      {"displacement_y", {Quantity::Displacement, 1, Measure::Length, Target::Node}},
      {"displacement_z", {Quantity::Displacement, 2, Measure::Length, Target::Node}},
      {"position_x", {Quantity::Position, 0, Measure::Length, Target::Node}},
      {"position_y", {Quantity::Position, 1, Measure::Length, Target::Node}},
      {"position_z", {Quantity::Position, 2, Measure::Length, Target::Node}},
      {"velocity_x", {Quantity::Velocity, 0, Measure::Velocity, Target::Node}},
      {"velocity_y", {Quantity::Velocity, 1, Measure::Velocity, Target::Node}},
      {"velocity_z", {Quantity::Velocity, 2, Measure::Velocity, Target::Node}},
      {"speed", {Quantity::Speed, 0, Measure::Velocity, Target::Node}},
      {"reaction_x", {Quantity::Reaction, 0, Measure::Reaction, Target::Node}},
      {"reaction_y", {Quantity::Reaction, 1, Measure::Reaction, Target::Node}},
      {"reaction_z", {Quantity::Reaction, 2, Measure::Reaction, Target::Node}},
      {"reaction_magnitude", {Quantity::ReactionMagnitude, 0, Measure::Reaction, Target::Node}},
      {"reaction_horizontal", {Quantity::ReactionHorizontal, 0, Measure::Reaction, Target::Node}},
      {"length_on_seabed", {Quantity::LengthOnSeabed, 0, Measure::Length, Target::Line}},
      {"end_tension", {Quantity::EndTension, 0, Measure::Force, Target::ElementEnd}},
      {"max_tension", {Quantity::MaxTension, 0, Measure::Force, Target::Model}},
      {"resultant_max", {Quantity::ResultantMax, 0, Measure::ForcePerLength, Target::Membrane}},
      {"resultant_min", {Quantity::ResultantMin, 0, Measure::ForcePerLength, Target::Membrane}},
      {"frequency", {Quantity::Frequency, 0, Measure::AngularFrequency, Target::Mode}},
      {"period", {Quantity::Period, 0, Measure::Time, Target::Mode}},
      {"cpu_seconds", {Quantity::CpuSeconds, 0, Measure::Time, Target::Run}},
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
    if (count == 0) return std::nullopt;  // no steps: reported by readSteps
    const auto checked = b.in.integer(n, path, 1, count);
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

// `element: ID` (1-based over the file's elements, then the lines' and the surfaces' elements) or
// `element: SURFACE.K` (the K-th element of a surface) or `element: LINE.K` (of a line), of one
// of the `types`.
std::optional<int> elementRef(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                              const std::vector<std::string>& types, const std::string& wanted) {
  std::optional<int> index;
  const std::string s = n.IsScalar() ? n.Scalar() : "";
  const size_t dot = s.find('.');
  if (dot != std::string::npos) {
    const std::string group = s.substr(0, dot), tail = s.substr(dot + 1);
    const std::vector<int>* elements = nullptr;
    if (const auto set = b.c.element_sets.find(group); set != b.c.element_sets.end())
      elements = &set->second;
    for (const CaseLine& line : b.c.named_lines)
      if (line.name == group) elements = &line.elements;
    int local = 0;
    const auto [end, error] = std::from_chars(tail.data(), tail.data() + tail.size(), local);
    const bool number = error == std::errc() && end == tail.data() + tail.size();
    if (!elements) {
      if (!b.broken_node_names.count(group))
        b.diag.error(n, path + ": unknown surface or line (got '" + s + "', expected SURFACE.K " +
                            "or LINE.K with SURFACE " + nameList(b.c.element_sets) +
                            " and LINE one of the lines)");
      return std::nullopt;
    }
    const int count = static_cast<int>(elements->size());
    if (!number && b.c.lines.count(group)) {  // LINE.end and the like: a node's name
      b.diag.error(n, path + ": not an element (got '" + s + "', a place on line '" + group +
                          "'; expected line: " + group + " with end:, or LINE.K for its K-th " +
                          "element, 1 to " + std::to_string(count) + ")");
      return std::nullopt;
    }
    if (!number || local < 1 || local > count) {
      b.diag.error(n, path + ": no such element of '" + group + "' (got '" + tail +
                          "', expected 1 to " + std::to_string(count) + ")");
      return std::nullopt;
    }
    index = (*elements)[local - 1];
  } else {
    const int count = static_cast<int>(b.element_types.size());
    if (count == 0) return std::nullopt;  // no elements: reported by readCase
    const auto id = b.in.integer(n, path, 1, count);
    if (!id) return std::nullopt;
    index = *id - 1;
  }
  const std::string& type = b.element_types[*index];
  if (type.empty()) return std::nullopt;  // broken, reported where it is defined
  if (std::find(types.begin(), types.end(), type) != types.end()) return index;
  b.diag.error(n, path + ": element " + s + " is a " + type + " (expected " + wanted + ")");
  return std::nullopt;
}

// A reaction is zero at a free dof: asking for one there is a mistake.
bool checkReaction(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                   const SummarySpec& s) {
  const ConditionsSpec& m = b.conditions;
  if (s.quantity == Quantity::Reaction && !m.held(s.node, s.component)) {
    b.diag.error(n, path + ": the reaction is zero (got a node whose " + "xyz"[s.component] +
                        " is free, expected a fixed dof)");
    return false;
  }
  const bool any = m.held(s.node, 0) || m.held(s.node, 1) || m.held(s.node, 2);
  const bool magnitude =
      s.quantity == Quantity::ReactionMagnitude || s.quantity == Quantity::ReactionHorizontal;
  if (magnitude && !any) {
    b.diag.error(n, path +
                        ": the reaction is zero (got a node without support, expected a node "
                        "with a fixed dof)");
    return false;
  }
  return true;
}

// Every key a quantity does not use is an error, so that a misplaced key is not ignored. A node
// quantity takes end: with line: (the line's end).
bool rejectUnused(CaseBuilder& b, Fields& f, const std::string& quantity, Target target) {
  bool ok = true;
  const bool on_line = f.find("line") != nullptr;
  for (const std::string key : {"node", "element", "end", "mode", "line"}) {
    const bool used =
        key == "node" ? target == Target::Node
        : key == "line"
            ? target == Target::Line || target == Target::Node || target == Target::ElementEnd
        : key == "element" ? target == Target::ElementEnd || target == Target::Membrane
        : key == "end"     ? target == Target::ElementEnd || (target == Target::Node && on_line)
                           : target == Target::Mode;
    if (f.find(key) && !used) {
      const bool end_without_line = key == "end" && target == Target::Node;
      b.diag.error(*f.find(key), f.path(key) + ": not used by " + quantity +
                                     (end_without_line ? " without line: (expected line: NAME "
                                                         "with end:, or node: alone)"
                                                       : ""));
      ok = false;
    }
  }
  return ok;
}

// The time span of step `index` in the run's time: every dynamic step before it advances the
// time by its duration, the other kinds keep it.
struct StepSpan {
  double start = 0.0, end = 0.0;
  std::string unit;      // " s"
  std::string expected;  // "expected 0 to 0.4 s, the time span of step 'shake'"
};

StepSpan stepSpan(const CaseBuilder& b, int index) {
  StepSpan span;
  for (int j = 0; j < index; ++j) span.start += b.c.steps[j].duration();
  span.end = span.start + b.c.steps[index].duration();
  span.unit = " " + unitNames(b.in.units).time;
  span.expected = "expected " + formatNumber(span.start) + " to " + formatNumber(span.end) +
                  span.unit + ", the time span of step '" + b.c.steps[index].name + "'";
  return span;
}

// A time inside the span, within the round-off of the run's time (a sum of time steps).
std::optional<double> timeInStep(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                                 const StepSpan& span) {
  const auto t = b.in.quantity(n, path, kind::kTime);
  if (!t) return std::nullopt;
  const double slack = 1e-9 * std::max(1.0, span.end);
  if (*t >= span.start - slack && *t <= span.end + slack) return t;
  b.diag.error(n, path + ": outside the step (got " + formatNumber(*t) + span.unit + ", " +
                      span.expected + ")");
  return std::nullopt;
}

// `window: {from, to}` of a statistic, each bound optional (default the step's start and end),
// inside the step, from before to.
bool readWindow(CaseBuilder& b, const YAML::Node& n, const std::string& path, const StepSpan& span,
                SummarySpec& s) {
  Fields w(b.diag, n, path, {"from", "to"});
  const YAML::Node* from = w.find("from");
  const YAML::Node* to = w.find("to");
  const auto t0 = from ? timeInStep(b, *from, w.path("from"), span) : span.start;
  const auto t1 = to ? timeInStep(b, *to, w.path("to"), span) : span.end;
  if (!t0 || !t1) return false;
  if (*t1 <= *t0) {
    b.diag.error(n, path + ": empty (got from " + formatNumber(*t0) + span.unit + " to " +
                        formatNumber(*t1) + span.unit + ", expected from before to)");
    return false;
  }
  if (from) s.from = *t0;  // else from the step's first state on
  if (to) s.to = *t1;      // else to its last
  return true;
}

// `at: TIME`, or `stat: max | min | mean | std` with an optional `window:`, of a quantity of
// dynamic step `index`: taken from the series of its accepted time steps (summary_series.hpp).
bool readReduction(CaseBuilder& b, Fields& f, int index, SummarySpec& s) {
  const YAML::Node* at = f.find("at");
  const YAML::Node* stat = f.find("stat");
  const YAML::Node* window = f.find("window");
  if (window && !stat) {
    b.diag.error(*window, f.path("window") + ": not used without stat (expected stat: max, min, " +
                              "mean or std with it)");
    return false;
  }
  if (!at && !stat) return true;
  if (at && stat) {
    b.diag.error(*stat, f.path("stat") + ": given with at (expected either at: TIME or stat:)");
    return false;
  }
  const std::string path = f.path(at ? "at" : "stat");
  if (index < 0) return false;  // no steps: reported by readSteps
  const StepSpec& step = b.c.steps[index];
  if (step.kind != StepSpec::Kind::Dynamic) {
    b.diag.error(at ? *at : *stat, path +
                                       ": a value over time of a step that is not dynamic (got "
                                       "step '" +
                                       step.name + "', expected step: naming a dynamic step)");
    return false;
  }
  const StepSpan span = stepSpan(b, index);
  if (at) {
    const auto t = timeInStep(b, *at, path, span);
    if (!t) return false;
    s.reduction = SummarySpec::Reduction::AtTime;
    s.at = *t;
    return true;
  }
  using R = SummarySpec::Reduction;
  const auto reduction = b.in.choice<R>(
      *stat, path, {{"max", R::Max}, {"min", R::Min}, {"mean", R::Mean}, {"std", R::Std}});
  if (!reduction) return false;
  s.reduction = *reduction;
  return !window || readWindow(b, *window, f.path("window"), span, s);
}

// A series over the whole of dynamic step `index`, or over its `window:` (the form of
// readSeriesQuantity): kept as a Max reduction, which carries the window.
bool readSeriesWindow(CaseBuilder& b, Fields& f, const YAML::Node& at, int index, SummarySpec& s) {
  if (index < 0) return false;  // no steps: reported by readSteps
  const StepSpec& step = b.c.steps[index];
  if (step.kind != StepSpec::Kind::Dynamic) {
    b.diag.error(at, f.path() + ": a series of a step that is not dynamic (got step '" + step.name +
                         "', expected the last step, or step:, to be a dynamic step)");
    return false;
  }
  s.reduction = SummarySpec::Reduction::Max;
  const YAML::Node* window = f.find("window");
  return !window || readWindow(b, *window, f.path("window"), stepSpan(b, index), s);
}

// `line: NAME` of length_on_seabed: the line's elements, their submerged weight per length, and
// its anchor (the lower end, if supported in z and at the bed's level), whose share of the laid
// weight counts as the bed's. The case must have seabed contact.
bool readSeabedLine(CaseBuilder& b, const YAML::Node& n, const std::string& path, SummarySpec& s) {
  const auto name = b.in.text(n, path);
  if (!name) return false;
  const auto line = b.line_elements.find(*name);
  if (line == b.line_elements.end()) {
    if (!b.broken_node_names.count(*name))
      b.diag.error(n, path + ": unknown line (got '" + *name + "', expected a line's name, " +
                          nameList(b.line_elements) + ")");
    return false;
  }
  if (!b.ocean.has_contact) {
    b.diag.error(n, path + ": no seabed contact in this case (got length_on_seabed, expected " +
                        "seabed: with water:)");
    return false;
  }
  for (int e : line->second) {  // a broken section: reported where it is defined
    const auto it = b.sections.find(b.origins.elements[e].section);
    if (it != b.sections.end() && !it->second) return false;
  }
  const CaseLine whole{*name, b.c.lines.at(*name), line->second, "", CaseLine::Anchor::None};
  const int sinks_not = seabedLine(whole, b.mesh, b.conditions, b.ocean, s);
  if (sinks_not < 0) return true;
  b.diag.error(n, path + ": the line does not sink (got a submerged weight of " +
                      formatNumber(s.element_weights.back()) + " per length in section " +
                      b.origins.elements[line->second[sinks_not]].section +
                      ", expected > 0: length_on_seabed is the length whose weight the bed "
                      "carries)");
  return false;
}

// One quantity of summary: (form Summary), or the series of one (form Series: no at: or stat:,
// the keys `other_keys` left to the caller).
enum class Form { Summary, Series };

std::optional<SummarySpec> readQuantity(CaseBuilder& b, const YAML::Node& value,
                                        const std::string& path, const std::string& name, int line,
                                        Form form,
                                        const std::vector<std::string>& other_keys = {}) {
  std::vector<std::string> keys = {"quantity", "node",  "element", "end",  "mode",
                                   "line",     "scale", "unit",    "step", "window"};
  if (form == Form::Summary) keys.insert(keys.end(), {"at", "stat"});
  keys.insert(keys.end(), other_keys.begin(), other_keys.end());
  Fields f(b.diag, value, path, keys);
  SummarySpec s;
  s.name = name;
  s.where = {b.diag.file(), line};
  const YAML::Node* q = f.require("quantity");
  const auto chosen = q ? b.in.choice(*q, f.path("quantity"), quantities()) : std::nullopt;
  s.scale = b.in.quantityOr(f, "scale", kind::kNumber, Limit::Any, 1.0);
  std::optional<int> step = -1;  // the last step
  if (const YAML::Node* n = f.find("step")) step = stepRef(b, *n, f.path("step"));
  if (!chosen) return std::nullopt;
  const QuantityInfo info = *chosen;
  if (form == Form::Series && (info.target == Target::Run || info.target == Target::Mode)) {
    b.diag.error(*q, f.path("quantity") + ": not a quantity over time (got " + q->Scalar() +
                         ", expected a quantity of the model's state in a dynamic step)");
    return std::nullopt;
  }
  if (!rejectUnused(b, f, q->Scalar(), info.target)) return std::nullopt;
  s.quantity = info.quantity;
  s.component = info.component;
  s.unit = unitOf(info.measure, b.in.units, axisymmetric(b));
  if (info.measure == Measure::Reaction && axisymmetric(b) && f.find("unit"))
    b.diag.error(*f.find("unit"), f.path("unit") +
                                      ": reactions of an axisymmetric model are per "
                                      "radian, in the case's units only (got unit:, "
                                      "expected no unit:)");
  else
    readReportUnit(b, f, info.measure, s);
  if (info.target == Target::Node) {
    const auto node = nodeOfEntry(b, f);
    if (!node) return std::nullopt;
    s.node = *node;
    const char* key = f.find("node") ? "node" : "end";
    if (!checkReaction(b, f.find(key) ? *f.find(key) : f.node(), f.path(key), s))
      return std::nullopt;
  }
  if (info.target == Target::Membrane) {
    const YAML::Node* el = f.require("element");
    const auto element = el ? elementRef(b, *el, f.path("element"),
                                         {"membrane", "axisymmetric_membrane"}, "a membrane")
                            : std::nullopt;
    if (!element) return std::nullopt;
    s.element = *element;
  }
  if (info.target == Target::Mode) {
    const YAML::Node* m = f.require("mode");
    const auto mode = m ? b.in.integer(*m, f.path("mode"), 1) : std::nullopt;
    if (!mode || !step) return std::nullopt;
    const int index = *step < 0 ? static_cast<int>(b.c.steps.size()) - 1 : *step;
    if (index < 0 || b.c.steps[index].kind != StepSpec::Kind::Modes) {
      b.diag.error(
          *q, f.path("quantity") + ": frequency of a step that is not a modes step (got " +
                  (index < 0 ? std::string("no steps") : "step '" + b.c.steps[index].name + "'") +
                  ", expected step: naming a modes step)");
      return std::nullopt;
    }
    if (*mode > b.c.steps[index].modes.modes) {
      b.diag.error(*m, f.path("mode") + ": beyond the modes computed (got " + m->Scalar() +
                           ", expected 1 to " + std::to_string(b.c.steps[index].modes.modes) +
                           ", the count of step '" + b.c.steps[index].name + "')");
      return std::nullopt;
    }
    s.mode = *mode;
  }
  if (info.target == Target::ElementEnd) {
    const auto at = elementEndOfEntry(b, f, [&b](const YAML::Node& n, const std::string& path) {
      return elementRef(b, n, path, {"cable", "spring"}, "a cable or spring");
    });
    if (!at) return std::nullopt;
    s.element = at->element;
    s.end = at->end;
  }
  if (info.target == Target::Line) {
    const YAML::Node* l = f.require("line");
    if (!l || !readSeabedLine(b, *l, f.path("line"), s)) return std::nullopt;
  }
  if (info.target == Target::Run)
    for (const char* key : {"step", "at", "stat", "window"})
      if (const YAML::Node* n = f.find(key)) {
        b.diag.error(*n, f.path(key) + ": not used by " + q->Scalar() +
                             " (the CPU time of the whole run, taken when it ends)");
        return std::nullopt;
      }
  if (!step) return std::nullopt;
  s.step = *step;
  const int index = *step < 0 ? static_cast<int>(b.c.steps.size()) - 1 : *step;
  const bool reduced = form == Form::Summary ? readReduction(b, f, index, s)
                                             : readSeriesWindow(b, f, value, index, s);
  if (!reduced) return std::nullopt;
  return s;
}

}  // namespace

void readSummary(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "summary"))
    if (auto spec = readQuantity(b, e.value, childPath("summary", e.key), e.key, lineOf(e.key_node),
                                 Form::Summary))
      b.c.summary.push_back(std::move(*spec));
}

std::optional<SummarySpec> readSeriesQuantity(CaseBuilder& b, const YAML::Node& n,
                                              const std::string& path, const std::string& name,
                                              const std::vector<std::string>& other_keys) {
  return readQuantity(b, n, path, name, lineOf(n), Form::Series, other_keys);
}

}  // namespace flexmoor::app
