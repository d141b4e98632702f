#pragma once
// Scenarios: a few keys that stand for a whole model. Those read into specifications
// (scenario_model.hpp) the reader builds on; the others, `scenario: NAME` in a case file, are
// expanded, before the case is read, into the sections they stand for (materials, sections,
// lines, bodies, supports, loads, steps and, unless the case gives its own, summary and figure);
// the expanded document is then read like any other, so every value is checked as usual. Values
// the scenario copies keep their place in the file for messages; values it derives are written
// in the case's units.
#include <yaml-cpp/yaml.h>

#include "apps/case/input/diagnostics.hpp"

namespace flexmoor::app {

// The document to read: `root` itself when it names no scenario or one read into
// specifications, else its expansion. Errors in the scenario's own keys go to `diag`.
YAML::Node expandScenario(Diagnostics& diag, const YAML::Node& root);

// The scenarios, one file each (scenario_NAME.cpp), listed in scenario.cpp: each turns a case
// that names it into the full document.
YAML::Node expandSubmergedTube(Diagnostics& diag, const YAML::Node& root);

}  // namespace flexmoor::app
