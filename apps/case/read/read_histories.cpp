// histories: named dimensionless time functions that scale loads, pressures and prescribed
// displacements in dynamic steps (a load with `history: NAME` is force * NAME(t)):
//   NAME: {type: sine, amplitude: A, period: T, phase: 0, offset: 0}  offset + A sin(2 pi t / T + phase)
//   NAME: {type: ramp, start: 0 s, duration: D}                       0 -> 1 over [start, start + D]
//   NAME: {type: table, times: [t0, t1, ...], values: [f0, f1, ...]}  piecewise linear
//   NAME: {type: rigid_point, arm: [x, y, z], component: x, offset: 0,
//          surge: {amplitude: 2 m, period: 10 s, phase: 0}, sway, heave,  (lengths)
//          roll: {amplitude: 5 deg, period: 20 s}, pitch, yaw}           (angles)
//     the displacement component (a length) of a point of a rigid body at `arm` from the body's
//     reference point, the body moving by its six motions about it (rigid_point_motion.hpp; each
//     optional, each a sine, a table {table: [[t, value], ...]} or a file {file, column}:
//     read_motion.hpp); a support moves it with `displacement: [1]` in the case's length unit.
//     `ramp: T` brings the motions in over T (default: one period of the slowest sine).
//   NAME: {type: rigid_motion, surge: ..., ..., yaw: ..., ramp: T}
//     the six motions of a rigid body alone (a body, not a scalar history): rigid_points that
//     say `motion: NAME` instead of motions of their own are points of that one body, which a
//     host program may drive (Case::rigid_motions).
#include <algorithm>
#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/case/read/read_motion.hpp"
#include "apps/common/format_number.hpp"
#include "libstruct/model/rigid_point_motion.hpp"

namespace flexmoor::app {
namespace {

std::vector<double> readNumbers(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                                const QuantityKind& kind, bool& ok) {
  std::vector<double> values;
  const std::vector<YAML::Node> items = listItems(b.diag, n, path);
  for (size_t i = 0; i < items.size(); ++i) {
    const auto v = b.in.quantity(items[i], itemPath(path, i), kind);
    ok = ok && v.has_value();
    values.push_back(v.value_or(0.0));
  }
  ok = ok && n.IsSequence();
  return values;
}

std::shared_ptr<const model::TimeFunction> readTable(CaseBuilder& b, Fields& f) {
  const YAML::Node* t = f.require("times");
  const YAML::Node* v = f.require("values");
  if (!t || !v) return nullptr;
  bool ok = true;
  const std::vector<double> times = readNumbers(b, *t, f.path("times"), kind::kTime, ok);
  const std::vector<double> values = readNumbers(b, *v, f.path("values"), kind::kNumber, ok);
  if (!ok) return nullptr;
  if (times.size() != values.size() || times.empty()) {
    b.diag.error(*v, f.path("values") + ": " + std::to_string(values.size()) + " values for " +
                         std::to_string(times.size()) +
                         " times (expected one value per time, at least one)");
    return nullptr;
  }
  if (std::adjacent_find(times.begin(), times.end(), std::greater_equal<double>()) != times.end()) {
    b.diag.error(*t, f.path("times") + ": not increasing (expected strictly increasing times)");
    return nullptr;
  }
  return std::make_shared<model::TableFunction>(times, values);
}

const char* const kRigidMotions[] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

}  // namespace

// Of a rigid_motion, of a rigid_point that gives its body's motion itself, or of a scenario's
// platform.
std::optional<model::RigidBodyMotion::Dofs> readRigidMotions(CaseBuilder& b, Fields& f) {
  model::RigidBodyMotion::Dofs motions;
  bool ok = true;
  for (int dof = 0; dof < 6; ++dof) {
    const YAML::Node* m = f.find(kRigidMotions[dof]);
    if (!m) continue;
    motions[dof] = readMotion(b.in, *m, f.path(kRigidMotions[dof]),
                              dof < 3 ? kind::kLength : kind::kNumber, b.diag.file());
    ok = ok && motions[dof];
  }
  if (!ok) return std::nullopt;
  // The motion starts at rest: ramped in over `ramp`, by default one period of its slowest
  // periodic motion (none for tables and files, which start as their samples say).
  double slowest = 0.0;
  for (const auto& m : motions)
    if (m) slowest = std::max(slowest, m->period());
  const YAML::Node* r = f.find("ramp");
  const double ramp = b.in.quantityOr(f, "ramp", kind::kTime, Limit::NonNegative, slowest);
  if (ramp > 0.0) {
    for (auto& m : motions)
      if (m) m = std::make_shared<model::RampedFunction>(m, 0.0, ramp);
    if (!r)
      b.diag.note(lineOf(f.node()), "the rigid-body motion is ramped in over " +
                                        formatNumber(ramp) +
                                        " s, one period of its slowest motion (ramp: 0 starts it "
                                        "at full speed)");
  }
  return motions;
}

namespace {

bool givesMotions(Fields& f) {
  for (const char* key : kRigidMotions)
    if (f.find(key)) return true;
  return f.find("ramp") != nullptr;
}

// `motion: NAME`: the rigid_motion of that name, which the point shares with the body's others.
std::shared_ptr<const model::RigidBodyMotion> rigidMotionRef(CaseBuilder& b, Fields& f) {
  const YAML::Node* n = f.find("motion");
  const std::optional<std::string> name = b.in.text(*n, f.path("motion"));
  if (!name) return nullptr;
  const auto found = b.c.rigid_motions.find(*name);
  if (found == b.c.rigid_motions.end()) {
    if (!b.broken_rigid_motions.count(*name))
      b.diag.error(*n, f.path("motion") + ": unknown rigid motion (got '" + *name + "', expected " +
                           nameList(b.c.rigid_motions) + ")");
    return nullptr;
  }
  return found->second;
}

std::shared_ptr<const model::TimeFunction> readRigidPoint(CaseBuilder& b, Fields& f) {
  const YAML::Node* a = f.require("arm");
  const YAML::Node* c = f.require("component");
  const auto arm = a ? b.in.vector3(*a, f.path("arm"), kind::kLength) : std::nullopt;
  const auto component =
      c ? b.in.choice<int>(*c, f.path("component"), {{"x", 0}, {"y", 1}, {"z", 2}}) : std::nullopt;
  const double offset = b.in.quantityOr(f, "offset", kind::kLength, Limit::Any, 0.0);
  std::shared_ptr<const model::RigidBodyMotion> body;
  if (f.find("motion")) {
    if (givesMotions(f)) {
      b.diag.error(f.node(), f.path() +
                                 ": both `motion:` and a motion of its own (expected either "
                                 "the name of a rigid_motion or surge, ..., yaw and ramp)");
      return nullptr;
    }
    body = rigidMotionRef(b, f);
  } else if (const auto motions = readRigidMotions(b, f)) {
    body = std::make_shared<model::RigidBodyMotion>(*motions);
  }
  if (!arm || !component || !body) return nullptr;
  return std::make_shared<model::RigidPointMotion>(body, *arm, *component, offset);
}

const std::vector<std::string> kRigidMotionKeys = {"type", "surge", "sway", "heave",
                                                   "roll", "pitch", "yaw",  "ramp"};

void readRigidMotion(CaseBuilder& b, const MapEntry& e) {
  Fields f(b.diag, e.value, childPath("histories", e.key), kRigidMotionKeys);
  const auto motions = readRigidMotions(b, f);
  if (!motions) {
    b.broken_rigid_motions.insert(e.key);
    return;
  }
  b.c.rigid_motions[e.key] = std::make_shared<model::RigidBodyMotion>(*motions);
}

std::shared_ptr<const model::TimeFunction> readHistory(CaseBuilder& b, const MapEntry& e) {
  const std::string path = childPath("histories", e.key);
  const std::string type = peekText(e.value, "type");
  Fields f(b.diag, e.value, path,
           type == "sine"
               ? std::vector<std::string>{"type", "amplitude", "period", "phase", "offset"}
           : type == "ramp"  ? std::vector<std::string>{"type", "start", "duration"}
           : type == "table" ? std::vector<std::string>{"type", "times", "values"}
           : type == "rigid_point"
               ? std::vector<std::string>{"type", "arm", "component", "offset", "motion", "surge",
                                          "sway", "heave", "roll", "pitch", "yaw", "ramp"}
               : std::vector<std::string>{"type"});
  const YAML::Node* t = f.require("type");
  if (!t) return nullptr;
  if (type == "sine") return readSine(b.in, f, kind::kNumber);
  if (type == "ramp") {
    const double start = b.in.quantityOr(f, "start", kind::kTime, Limit::NonNegative, 0.0);
    const YAML::Node* d = f.require("duration");
    const auto duration =
        d ? b.in.quantity(*d, f.path("duration"), kind::kTime, Limit::Positive) : std::nullopt;
    if (!duration) return nullptr;
    return std::make_shared<model::RampFunction>(start, *duration);
  }
  if (type == "table") return readTable(b, f);
  if (type == "rigid_point") return readRigidPoint(b, f);
  b.in.choice<int>(
      *t, f.path("type"),
      {{"sine", 0}, {"ramp", 1}, {"table", 2}, {"rigid_point", 3}, {"rigid_motion", 4}});
  return nullptr;
}

}  // namespace

void readHistories(CaseBuilder& b, const YAML::Node& n) {
  // The rigid motions first, for the points that name them wherever they are in the map.
  const std::vector<MapEntry> entries = mapEntries(b.diag, n, "histories");
  for (const MapEntry& e : entries)
    if (peekText(e.value, "type") == "rigid_motion") readRigidMotion(b, e);
  for (const MapEntry& e : entries)
    if (peekText(e.value, "type") != "rigid_motion") b.histories[e.key] = readHistory(b, e);
}

std::shared_ptr<const model::TimeFunction> historyRef(CaseBuilder& b, const YAML::Node& n,
                                                      const std::string& path) {
  const std::optional<std::string> name = b.in.text(n, path);
  if (!name) return nullptr;
  const auto found = b.histories.find(*name);
  if (found == b.histories.end() && b.c.rigid_motions.count(*name)) {
    b.diag.error(n, path + ": '" + *name +
                        "' is a rigid_motion, which moves the points of a body (expected a "
                        "history: a rigid_point of that motion moves one point's dof)");
    return nullptr;
  }
  if (found == b.histories.end()) {
    b.diag.error(n, path + ": unknown history (got '" + *name + "', expected " +
                        nameList(b.histories) + ")");
    return nullptr;
  }
  return found->second;
}

}  // namespace flexmoor::app
