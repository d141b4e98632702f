#include "apps/case/read/read_seabed_friction.hpp"

#include <vector>

#include "apps/case/read/read_fields.hpp"

namespace flexmoor::app {
namespace {

// A value given in SI (libhydro's defaults), in the case's system.
double fromSi(const CaseBuilder& b, double value, const QuantityKind& kind) {
  return value / systemScale(kind.dimension, b.in.units);
}

// friction: {law: ..., coefficient, ...}: the law's own keys.
bool readFrictionMap(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                     hydro::SeabedProperties& bed) {
  const std::string law = peekText(n, "law");
  // The law's keys; every law's while the law is not known (it is reported alone).
  std::vector<std::string> keys = {"law", "coefficient"};
  if (law != "moordyn") keys.push_back("slip_speed");
  if (law != "coulomb") keys.insert(keys.end(), {"damping", "static_dynamic_scale"});
  Fields f(b.diag, n, path, keys);
  const YAML::Node* l = f.require("law");
  const auto mu = requiredQuantity(b, f, "coefficient", kind::kNumber, Limit::NonNegative);
  std::optional<hydro::FrictionLaw> chosen;
  if (l)
    chosen = b.in.choice(
        *l, f.path("law"),
        std::vector<std::pair<std::string, hydro::FrictionLaw>>{
            {"coulomb", hydro::FrictionLaw::Coulomb}, {"moordyn", hydro::FrictionLaw::MoorDyn}});
  if (!chosen || !mu) return false;
  bed.friction_law = chosen.value_or(hydro::FrictionLaw::Coulomb);
  bed.friction = *mu;
  if (bed.friction_law == hydro::FrictionLaw::Coulomb) {
    const auto slip = optionalQuantity(b, f, "slip_speed", kind::kVelocity, Limit::Positive,
                                       fromSi(b, bed.slip_speed, kind::kVelocity));
    if (slip) bed.slip_speed = *slip;
    return slip.has_value();
  }
  const auto damping = optionalQuantity(b, f, "damping", kind::kDashpot, Limit::NonNegative,
                                        fromSi(b, bed.friction_damping, kind::kDashpot));
  const auto scale = optionalQuantity(b, f, "static_dynamic_scale", kind::kNumber, Limit::Positive,
                                      bed.static_dynamic_scale);
  if (!damping || !scale) return false;
  bed.friction_damping = *damping;
  bed.static_dynamic_scale = *scale;
  return true;
}

}  // namespace

bool readSeabedFriction(CaseBuilder& b, const Fields& seabed, hydro::SeabedProperties& bed) {
  const YAML::Node* friction = seabed.find("friction");
  const YAML::Node* slip = seabed.find("slip_speed");
  if (friction && friction->IsMap()) {
    if (slip) {
      b.diag.error(*slip, seabed.path("slip_speed") +
                              ": give it in friction: with the law it is of (got slip_speed "
                              "beside friction: {law: ...}, expected friction: {law: coulomb, "
                              "coefficient: MU, slip_speed: V})");
      return false;
    }
    return readFrictionMap(b, *friction, seabed.path("friction"), bed);
  }
  // friction: MU, flexmoor's Coulomb law, and its slip_speed beside it.
  const auto mu =
      optionalQuantity(b, seabed, "friction", kind::kNumber, Limit::NonNegative, bed.friction);
  const auto v = optionalQuantity(b, seabed, "slip_speed", kind::kVelocity, Limit::Positive,
                                  fromSi(b, bed.slip_speed, kind::kVelocity));
  if (!mu || !v) return false;
  bed.friction_law = hydro::FrictionLaw::Coulomb;
  bed.friction = *mu;
  bed.slip_speed = *v;
  return true;
}

}  // namespace flexmoor::app
