#pragma once
// What the scenarios (scenario_*.cpp) share to write the document they expand into: numbers
// written back in full precision, flow lists, and the case's unit system read before the case is.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "apps/case/case.hpp"

namespace flexmoor::app {

// A value the scenario derives, in the case's units, to 17 digits.
std::string scenarioNumber(double v);
// [a, b, c] as a YAML sequence of scalars.
YAML::Node flowSequence(std::initializer_list<std::string> items);
// `units: US` or else SI (the reader checks the key itself later).
UnitSystem scenarioUnits(const YAML::Node& root);
// The model's keys a scenario writes: a case that names a scenario does not give them itself.
const std::vector<std::string>& scenarioGeneratedKeys();

}  // namespace flexmoor::app
