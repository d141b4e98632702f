#include "apps/case/scenario_yaml.hpp"

#include <sstream>

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

}  // namespace flexmoor::app
