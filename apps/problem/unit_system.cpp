#include "apps/problem/unit_system.hpp"

namespace flexmoor::app {

UnitNames unitNames(UnitSystem system) {
  if (system == UnitSystem::US) return {"ft", "slug", "s", "lbf", "lbf/ft^2"};
  return {"m", "kg", "s", "N", "Pa"};
}

std::string unitSystemName(UnitSystem system) {
  const UnitNames u = unitNames(system);
  return std::string(system == UnitSystem::US ? "US" : "SI") + " (" + u.length + ", " + u.mass +
         ", " + u.time + ", " + u.force + ")";
}

}  // namespace flexmoor::app
