#pragma once
// A case stated in code: the specifications a program fills to build a Case without a case file
// (buildCase, apps/case/build/build_case.hpp): the mesh, its supports and loads, the ocean, the
// liquids that fill membranes, the lines that start on their catenary, the rigid bodies in prescribed motion, the steps, what the
// results hold and the named lines they speak of. The case reader fills the same specifications
// from YAML and builds them with the same builders, so a case read from its file and the same
// case stated here build the same model.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/problem/case_line.hpp"
#include "apps/problem/catenary_start_spec.hpp"
#include "apps/problem/conditions_spec.hpp"
#include "apps/problem/enclosed_fluid_spec.hpp"
#include "apps/problem/figure_spec.hpp"
#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/ocean_spec.hpp"
#include "apps/problem/output_fields.hpp"
#include "apps/problem/step_spec.hpp"
#include "apps/problem/summary_spec.hpp"
#include "apps/problem/unit_system.hpp"
#include "libstruct/model/rigid_body_motion.hpp"

namespace flexmoor::app {

struct CaseSpec {
  std::string name = "case";  // names the results files
  std::string title;
  UnitSystem units = UnitSystem::SI;  // the system every value is in
  MeshSpec mesh;
  ConditionsSpec conditions;
  OceanSpec ocean;                                 // none without has_water
  std::vector<EnclosedFluidSpec> enclosed_fluids;  // liquids that fill membranes
  std::vector<CatenaryStartSpec> catenary_starts;
  // By name: the rigid bodies whose motion the supports' histories follow (model::RigidPointMotion), so
  // that a host program may drive them (RigidBodyMotion::drive, the C API's coupled bodies).
  std::map<std::string, std::shared_ptr<model::RigidBodyMotion>> rigid_motions;
  // The histories of supports and loads by name, for the messages that speak of them.
  std::map<std::string, std::shared_ptr<const model::TimeFunction>> histories;
  std::vector<StepSpec> steps;  // in the order they run
  std::vector<SummarySpec> summary;
  OutputFields output = OutputFields::all();
  std::optional<FigureSpec> figure;
  std::vector<CaseLine> lines;  // named lines: their nodes, start to end, and elements
  std::map<std::string, std::vector<int>> surfaces;      // the nodes of each named surface
  std::map<std::string, std::vector<int>> element_sets;  // named groups of elements (surfaces)
};

}  // namespace flexmoor::app
