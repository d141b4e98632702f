#include "apps/case/scenarios/scenario_keys.hpp"

#include <sstream>

#include "apps/case/input/physical_range.hpp"
#include "apps/case/input/units.hpp"

namespace flexmoor::app {

const std::vector<std::string>& scenarioGeneratedKeys() {
  static const std::vector<std::string> keys = {"materials", "sections", "nodes",  "lines",
                                                "surfaces",  "elements", "bodies", "supports",
                                                "loads",     "node_sets"};
  return keys;
}

void refuseGeneratedKeys(Diagnostics& diag, const Fields& top, const std::string& scenario,
                         const std::string& own_keys) {
  for (const std::string& key : scenarioGeneratedKeys())
    if (top.find(key))
      diag.error(top.keyLine(key), key + ": given with scenario: " + scenario + " (got " + key +
                                       ":, expected the scenario's keys " + own_keys + " and no " +
                                       key + ": of the case's own)");
}

void checkScenarioStepKeys(Diagnostics& diag, const Fields& top,
                           std::initializer_list<const char*> keys) {
  std::string named;
  for (const char* key : keys) named += (named.empty() ? "" : " and ") + std::string(key) + ":";
  for (const char* key : keys) {
    const YAML::Node* n = top.find(key);
    if (n && top.find("steps"))
      diag.error(*n, std::string(key) + ": given with steps: (expected the scenario's " + named +
                         ", or steps: of the case's own)");
    else if (n && !n->IsMap())
      diag.error(*n, std::string(key) + ": expected a map of the step's keys (got " +
                         describeNode(*n) + ")");
  }
}

ScenarioWater readScenarioWater(Input& in, Fields& top, UnitSystem units) {
  ScenarioWater w;
  if (const YAML::Node* water = top.require("water")) {
    const YAML::Node d = (*water)["density"], h = (*water)["depth"];
    if (d) {
      const auto density = in.quantity(d, "water.density", kind::kDensity, Limit::Positive);
      if (density && inPhysicalRange(in, d, "water.density", *density, kWaterDensityRange))
        w.density = *density;
    }
    if (h) w.depth = in.quantity(h, "water.depth", kind::kLength, Limit::Positive).value_or(0.0);
  }
  w.gravity = standardGravity(units);
  if (const YAML::Node* n = top.find("gravity")) {
    const auto g = in.quantity(*n, "gravity", kind::kAcceleration, Limit::Positive);
    if (g && inPhysicalRange(in, *n, "gravity", *g, kGravityRange)) w.gravity = *g;
  }
  return w;
}

}  // namespace flexmoor::app
