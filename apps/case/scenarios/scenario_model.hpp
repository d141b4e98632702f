#pragma once
// The scenarios read into specifications: a scenario's own keys become the case it stands for
// (a CaseSpec, as a program states it: spread_mooring.hpp), which the reader then builds on,
// reading the case's own sections (waves, current, seabed, histories, steps, summary, figure,
// output) on top of it.
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
// (for the messages), and its steps.
struct ScenarioModel {
  CaseSpec spec;
  ModelOrigins origins;
  std::vector<ScenarioStep> steps;
};

struct SpecScenario {
  const char* name;
  const std::vector<std::string>& (*keys)();  // the keys of its case file
  // Its own keys read into the case it stands for; nullopt after reporting what is wrong.
  std::optional<ScenarioModel> (*read)(CaseBuilder& b, Fields& top);
  // The summary and figure it gives a case that gives none of its own (after they are read).
  void (*add_defaults)(CaseBuilder& b, Fields& top, const ScenarioModel& model);
};

// The scenario read into specifications that the document names, or null.
const SpecScenario* specScenarioOf(const YAML::Node& root);
// Their names, for the message that lists every scenario.
std::vector<std::string> specScenarioNames();

// The scenario's model where the reader reads the case's other sections on top of it: its mesh,
// named lines, supports, gravity, catenary starts and named histories and rigid motions
// (before the histories are read), then its Morison loads, bodies and, unless the case gives its
// own seabed:, its seabed contact (after the ocean is read).
void addScenarioModel(CaseBuilder& b, const ScenarioModel& model);
void addScenarioOcean(CaseBuilder& b, const ScenarioModel& model, bool seabed_given);
// The steps: the case's own steps:, else the scenario's.
void readScenarioSteps(CaseBuilder& b, Fields& top, const ScenarioModel& model);

// The scenarios (read_NAME.cpp).
const std::vector<std::string>& spreadMooringKeys();
std::optional<ScenarioModel> readSpreadMooring(CaseBuilder& b, Fields& top);
void addSpreadMooringDefaults(CaseBuilder& b, Fields& top, const ScenarioModel& model);
const std::vector<std::string>& singlePointMoorKeys();
std::optional<ScenarioModel> readSinglePointMoor(CaseBuilder& b, Fields& top);
void addSinglePointMoorDefaults(CaseBuilder& b, Fields& top, const ScenarioModel& model);

}  // namespace flexmoor::app
