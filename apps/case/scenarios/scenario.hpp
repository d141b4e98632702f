#pragma once
// Scenarios: a few keys that stand for a whole model. spread_mooring is read into specifications
// (spread_mooring.hpp) that the reader builds on; the others, `scenario: NAME` in a case file, are
// expanded, before the case is read, into the sections they stand for (materials, sections,
// lines, bodies, supports, loads, steps and, unless the case gives its own, summary and figure);
// the expanded document is then read like any other, so every value is checked as usual. Values
// the scenario copies keep their place in the file for messages; values it derives are written
// in the case's units.
#include <yaml-cpp/yaml.h>

#include "apps/case/check/model_checks.hpp"
#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/case_spec.hpp"

namespace flexmoor::app {

struct CaseBuilder;

// A scenario stated as specifications (spread_mooring.hpp): the case it stands for and where
// each of its nodes and elements comes from in the file, for the messages.
struct ScenarioModel {
  CaseSpec spec;
  ModelOrigins origins;
};

// scenario: spread_mooring (read_spread_mooring.cpp): the keys of its case file, and its own
// keys read into the case it stands for (nullopt after reporting what is wrong).
const std::vector<std::string>& spreadMooringKeys();
std::optional<ScenarioModel> readSpreadMooring(CaseBuilder& b, Fields& top);
// The scenario's model where the reader reads the case's other sections on top of it: its mesh,
// named lines, supports, gravity, catenary starts and named histories and rigid motions
// (before the histories are read), then its Morison loads, bodies and, unless the case gives its
// own seabed:, its seabed contact (after the ocean is read).
void addScenarioModel(CaseBuilder& b, const ScenarioModel& model);
void addScenarioOcean(CaseBuilder& b, const ScenarioModel& model, bool seabed_given);
// The steps: the case's own steps:, else the static step with the keys of statics: and, with
// dynamic:, a dynamic step of its keys.
void readScenarioSteps(CaseBuilder& b, Fields& top);
// The summary and figure the scenario gives a case that gives none of its own.
void addScenarioDefaults(CaseBuilder& b, Fields& top, const ScenarioModel& model);
// Whether the document names scenario: spread_mooring.
bool isSpreadMooring(const YAML::Node& root);

// The document to read: `root` itself when it names no scenario or spread_mooring, else its
// expansion. Errors in the scenario's own keys go to `diag`.
YAML::Node expandScenario(Diagnostics& diag, const YAML::Node& root);

// The scenarios, one file each (scenario_NAME.cpp), listed in scenario.cpp: each turns a case
// that names it into the full document.
YAML::Node expandSinglePointMoor(Diagnostics& diag, const YAML::Node& root);
YAML::Node expandSubmergedTube(Diagnostics& diag, const YAML::Node& root);

}  // namespace flexmoor::app
