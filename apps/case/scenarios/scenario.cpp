// The table of scenarios: `scenario: NAME` picks the expansion that writes the full case.
#include "apps/case/scenarios/scenario.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "apps/case/input/yaml_input.hpp"
#include "apps/case/scenarios/scenario_model.hpp"

namespace flexmoor::app {
namespace {

struct Scenario {
  const char* name;
  YAML::Node (*expand)(Diagnostics&, const YAML::Node&);
};

const Scenario kScenarios[] = {
    {"submerged_tube", expandSubmergedTube},
};

// Every scenario's name, in alphabetical order: "single_point_moor | spread_mooring | ...".
std::string scenarioNames() {
  std::vector<std::string> names = specScenarioNames();
  for (const Scenario& s : kScenarios) names.push_back(s.name);
  std::sort(names.begin(), names.end());
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : " | ") + name;
  return list;
}

}  // namespace

YAML::Node expandScenario(Diagnostics& diag, const YAML::Node& root) {
  if (!root.IsMap() || !root["scenario"]) return root;
  const YAML::Node s = root["scenario"];
  if (specScenarioOf(root)) return root;
  if (s.IsScalar())
    for (const Scenario& known : kScenarios)
      if (s.Scalar() == known.name) return known.expand(diag, root);
  diag.error(s,
             "scenario: unknown (got " + describeNode(s) + ", expected " + scenarioNames() + ")");
  return root;
}

}  // namespace flexmoor::app
