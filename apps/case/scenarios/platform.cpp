#include "apps/case/scenarios/platform.hpp"

#include "apps/case/input/units.hpp"
#include "apps/case/read/read_motion.hpp"
#include "apps/case/scenarios/yaml_text.hpp"

namespace flexmoor::app {
namespace {

const char* const kMotions[] = {"surge", "sway", "heave", "roll", "pitch", "yaw"};

}  // namespace

std::optional<PlatformMotion> readPlatform(Input& in, const YAML::Node& n) {
  Fields f(in.diag, n, "platform",
           {"reference", "surge", "sway", "heave", "roll", "pitch", "yaw", "ramp"});
  PlatformMotion p;
  bool ok = n.IsMap();
  if (const YAML::Node* r = f.find("reference")) {
    const auto reference = in.vector3(*r, f.path("reference"), kind::kLength);
    ok = ok && reference;
    if (reference) p.reference = *reference;
  }
  for (int dof = 0; dof < 6; ++dof)
    if (const YAML::Node* m = f.find(kMotions[dof])) {
      // Read here for its errors (at their lines); the history reads it again from the same node.
      ok = ok && readMotion(in, *m, f.path(kMotions[dof]), dof < 3 ? kind::kLength : kind::kNumber,
                            in.diag.file());
      p.motions[dof] = *m;
    }
  if (const YAML::Node* r = f.find("ramp")) {
    ok = ok && in.quantity(*r, f.path("ramp"), kind::kTime, Limit::NonNegative);
    p.ramp = *r;
  }
  if (ok && n.IsMap() && !f.find("surge") && !f.find("sway") && !f.find("heave") &&
      !f.find("roll") && !f.find("pitch") && !f.find("yaw")) {
    in.diag.error(n,
                  "platform: no motion (expected at least one of surge, sway, heave, roll, "
                  "pitch, yaw)");
    ok = false;
  }
  if (!ok) return std::nullopt;
  return p;
}

YAML::Node platformMotionHistory(const PlatformMotion& p) {
  YAML::Node h;
  h["type"] = "rigid_motion";
  // A clone, not the case's node: yaml-cpp merges the memory of the whole document a node belongs
  // to into the tree it is put in.
  for (int dof = 0; dof < 6; ++dof)
    if (const auto& m = p.motions[dof]) h[kMotions[dof]] = YAML::Clone(*m);
  if (p.ramp) h["ramp"] = YAML::Clone(*p.ramp);
  return h;
}

YAML::Node platformPointHistory(const PlatformMotion& p, const Eigen::Vector3d& point,
                                const Eigen::Vector3d& from, int component) {
  YAML::Node h;
  h["type"] = "rigid_point";
  h["motion"] = "platform";
  const Eigen::Vector3d arm = point - p.reference;
  h["arm"] =
      flowSequence({scenarioNumber(arm.x()), scenarioNumber(arm.y()), scenarioNumber(arm.z())});
  h["component"] = std::string(1, "xyz"[component]);
  h["offset"] = scenarioNumber(point[component] - from[component]);
  return h;
}

}  // namespace flexmoor::app
