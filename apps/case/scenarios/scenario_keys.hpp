#pragma once
// What the scenarios' readers (read_*.cpp) share: the keys a scenario stands for, its step keys,
// and the water every ocean scenario needs.
#include <initializer_list>
#include <string>
#include <vector>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

// The model's keys a scenario stands for: a case that names a scenario does not give them itself.
const std::vector<std::string>& scenarioGeneratedKeys();
// Reports each generated key the case gives itself, naming the scenario and `own_keys` (the
// scenario's keys that stand for them, as text).
void refuseGeneratedKeys(Diagnostics& diag, const Fields& top, const std::string& scenario,
                         const std::string& own_keys);

// Checks the scenario's own step keys (e.g. {"statics", "dynamic"}): each a map, and none given
// together with steps: of the case's own.
void checkScenarioStepKeys(Diagnostics& diag, const Fields& top,
                           std::initializer_list<const char*> keys);

// The water every ocean scenario needs: `water: {density, depth}` (required) and `gravity:`
// (default standard gravity in the case's units).
struct ScenarioWater {
  double density = 0.0, depth = 0.0, gravity = 0.0;
};
ScenarioWater readScenarioWater(Input& in, Fields& top, UnitSystem units);

}  // namespace flexmoor::app
