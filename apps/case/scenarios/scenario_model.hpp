#pragma once
// Scenarios: a few keys that stand for a whole model (`scenario: NAME` in a case file). A
// scenario's own keys are read into the specifications of a function that states the case it
// stands for (a CaseSpec, as a program states it: spread_mooring.hpp, single_point_moor.hpp,
// submerged_tube.hpp); the reader builds on that case, reading the case file's own sections
// (waves, current, seabed, histories, steps, summary, figure, output) on top of it. Nothing is
// written as YAML and read again.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "apps/case/check/model_checks.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/case_spec.hpp"

namespace flexmoor::app {

struct CaseBuilder;

// A step the scenario stands for: read from the keys of its case file's `key:` over `base`,
// always or only when the key is given; none when the case gives its own steps:.
struct ScenarioStep {
  std::string key;
  StepSpec base;
  bool always = false;
};

// The case a scenario stands for, where each of its nodes and elements comes from in the file
// (for the messages), its steps, and its default summary for the steps the case has.
struct ScenarioModel {
  CaseSpec spec;
  ModelOrigins origins;
  std::vector<ScenarioStep> steps;
  std::function<std::vector<SummarySpec>(const CaseSpec&)> summary;
};

struct Scenario {
  const char* name;
  const std::vector<std::string>& (*keys)();  // the keys of its case file
  // Its own keys read into the case it stands for; nullopt after reporting what is wrong.
  std::optional<ScenarioModel> (*read)(CaseBuilder& b, Fields& top);
};

// The scenario the document names, or null for none; an unknown one is reported.
const Scenario* scenarioOf(Diagnostics& diag, const YAML::Node& root);

// The scenario's model where the reader reads the case's other sections on top of it: its mesh,
// named lines, supports, gravity, catenary starts and named histories and rigid motions
// (before the histories are read), then its Morison loads, bodies and, unless the case gives its
// own seabed:, its seabed contact (after the ocean is read).
void addScenarioModel(CaseBuilder& b, const ScenarioModel& model);
void addScenarioOcean(CaseBuilder& b, const ScenarioModel& model, bool seabed_given);
// The steps: the case's own steps:, else the scenario's.
void readScenarioSteps(CaseBuilder& b, Fields& top, const ScenarioModel& model);
// The summary (for the steps read) and the figure (less the series the records do not hold) the
// scenario gives a case that gives none of its own, after those are read.
void addScenarioDefaults(CaseBuilder& b, Fields& top, const ScenarioModel& model);

// The scenarios (read_NAME.cpp).
const std::vector<std::string>& spreadMooringKeys();
std::optional<ScenarioModel> readSpreadMooring(CaseBuilder& b, Fields& top);
const std::vector<std::string>& singlePointMoorKeys();
std::optional<ScenarioModel> readSinglePointMoor(CaseBuilder& b, Fields& top);
const std::vector<std::string>& submergedTubeKeys();
std::optional<ScenarioModel> readSubmergedTube(CaseBuilder& b, Fields& top);

}  // namespace flexmoor::app
