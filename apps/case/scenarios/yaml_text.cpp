#include "apps/case/scenarios/yaml_text.hpp"

#include <sstream>

#include "apps/case/input/physical_range.hpp"
#include "apps/case/input/units.hpp"

namespace flexmoor::app {

std::string scenarioNumber(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

YAML::Node flowSequence(std::initializer_list<std::string> items) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (const std::string& i : items) n.push_back(i);
  return n;
}

UnitSystem scenarioUnits(const YAML::Node& root) {
  const YAML::Node u = root["units"];
  return u && u.IsScalar() && u.Scalar() == "US" ? UnitSystem::US : UnitSystem::SI;
}

const std::vector<std::string>& scenarioGeneratedKeys() {
  static const std::vector<std::string> keys = {"materials", "sections", "nodes",  "lines",
                                                "surfaces",  "elements", "bodies", "supports",
                                                "loads",     "node_sets"};
  return keys;
}

YAML::Node nodeSeries(const std::string& quantity, const YAML::Node& node) {
  YAML::Node n;
  n["quantity"] = quantity;
  n["node"] = node;
  return n;
}

YAML::Node firstElementTensionSeries() {
  YAML::Node tension;
  tension["quantity"] = "tension_end";
  tension["element"] = 1;
  tension["end"] = 1;
  return tension;
}

YAML::Node defaultFigure(const Fields& top, const std::vector<YAML::Node>& series) {
  const YAML::Node* output = top.find("output");
  const YAML::Node listed = output && output->IsMap() ? (*output)["fields"] : YAML::Node();
  const auto written = [&](const std::string& quantity) {
    if (!listed.IsSequence()) return true;
    const auto field = OutputFields::ofVariable(quantity);
    for (const YAML::Node& name : listed)
      if (field && name.IsScalar() && name.Scalar() == OutputFields::name(*field)) return true;
    return false;
  };
  YAML::Node figure;
  for (const YAML::Node& s : series)
    if (written(s["quantity"].as<std::string>())) figure["series"].push_back(s);
  return figure;
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
