#include "apps/case/scenarios/platform.hpp"

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

std::optional<PlatformSpec> readPlatform(CaseBuilder& b, const YAML::Node& n) {
  Fields f(b.diag, n, "platform",
           {"reference", "surge", "sway", "heave", "roll", "pitch", "yaw", "ramp"});
  PlatformSpec p;
  bool ok = n.IsMap();
  if (const YAML::Node* r = f.find("reference")) {
    const auto reference = b.in.vector3(*r, f.path("reference"), kind::kLength);
    ok = ok && reference;
    if (reference) p.reference = *reference;
  }
  const auto motions = readRigidMotions(b, f);
  ok = ok && motions;
  if (ok && !f.find("surge") && !f.find("sway") && !f.find("heave") && !f.find("roll") &&
      !f.find("pitch") && !f.find("yaw")) {
    b.diag.error(n,
                 "platform: no motion (expected at least one of surge, sway, heave, roll, "
                 "pitch, yaw)");
    ok = false;
  }
  if (!ok) return std::nullopt;
  p.motion = std::make_shared<model::RigidBodyMotion>(*motions);
  return p;
}

}  // namespace flexmoor::app
