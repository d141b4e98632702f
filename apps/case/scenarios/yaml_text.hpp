#pragma once
// What the scenarios (scenario_*.cpp) share to write the document they expand into: numbers
// written back in full precision, flow lists, and the case's unit system read before the case is.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

// A value the scenario derives, in the case's units, to 17 digits.
std::string scenarioNumber(double v);
// [a, b, c] as a YAML sequence of scalars.
YAML::Node flowSequence(std::initializer_list<std::string> items);
// `units: US` or else SI (the reader checks the key itself later).
UnitSystem scenarioUnits(const YAML::Node& root);
// The model's keys a scenario writes: a case that names a scenario does not give them itself.
const std::vector<std::string>& scenarioGeneratedKeys();
// A figure series `{quantity, node}` (the node a name or a map such as {at: [x, y, z]}), and the
// series of the first element's tension at its first end.
YAML::Node nodeSeries(const std::string& quantity, const YAML::Node& node);
YAML::Node firstElementTensionSeries();
// The scenario's default figure of `series`, less the series whose field the case's `output:
// fields:` leaves out (read as given: readOutput checks the list); a null node when none is left.
YAML::Node defaultFigure(const Fields& top, const std::vector<YAML::Node>& series);
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
