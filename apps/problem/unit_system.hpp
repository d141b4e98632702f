#pragma once
// The consistent unit system a case is given in, and the names of its units.
#include <string>

namespace flexmoor::app {

// A consistent unit system: US = ft, slug, s, lbf; SI = m, kg, s, N.
enum class UnitSystem { SI, US };

struct UnitNames {
  std::string length, mass, time, force, pressure;
};
UnitNames unitNames(
    UnitSystem system);  // {"ft","slug","s","lbf","lbf/ft^2"} or {"m","kg","s","N","Pa"}

// "US (ft, slug, s, lbf)" or "SI (m, kg, s, N)": what the results' unit_system attribute says.
std::string unitSystemName(UnitSystem system);

}  // namespace flexmoor::app
