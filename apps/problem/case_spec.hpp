#pragma once
// A case stated in code: the specifications a program fills to build a Case without a case file
// (buildCase, apps/case/build/build_case.hpp): the mesh, its supports and loads, the steps, and
// the named lines the results speak of. The case reader fills the same MeshSpec and
// ConditionsSpec from YAML, so a case read from its file and the same case stated here build the
// same model.
#include <string>
#include <vector>

#include "apps/problem/case_line.hpp"
#include "apps/problem/conditions_spec.hpp"
#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/step_spec.hpp"
#include "apps/problem/summary_spec.hpp"
#include "apps/problem/unit_system.hpp"

namespace flexmoor::app {

struct CaseSpec {
  std::string name = "case";  // names the results files
  std::string title;
  UnitSystem units = UnitSystem::SI;  // the system every value is in
  MeshSpec mesh;
  ConditionsSpec conditions;
  std::vector<StepSpec> steps;  // in the order they run
  std::vector<SummarySpec> summary;
  std::vector<CaseLine> lines;  // named lines: their nodes, start to end, and elements
};

}  // namespace flexmoor::app
