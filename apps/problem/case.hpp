#pragma once
// A case: the model it builds, the analysis steps to run in order, the summary quantities it
// declares and what its results hold, as read from its YAML file or built by a program.
// Everything is in the case's consistent unit system.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/problem/case_line.hpp"
#include "apps/problem/figure_spec.hpp"
#include "apps/problem/output_fields.hpp"
#include "apps/problem/sea_origin.hpp"
#include "apps/problem/step_spec.hpp"
#include "apps/problem/summary_spec.hpp"
#include "apps/problem/unit_system.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/model/rigid_body_motion.hpp"

namespace flexmoor::hydro {
class Bathymetry;
class Sea;
}  // namespace flexmoor::hydro

namespace flexmoor::app {

struct Case {
  std::string name;   // `name:` in the file, or the file's stem
  std::string title;  // optional one-line description
  std::string file;   // path it was read from
  UnitSystem units = UnitSystem::SI;
  std::unique_ptr<model::Model> model;  // equations already numbered
  std::vector<StepSpec> steps;
  std::vector<SummarySpec> summary;
  std::optional<FigureSpec> figure;
  OutputFields output = OutputFields::all();          // `output: fields:`: what the records hold
  std::map<std::string, std::vector<int>> node_sets;  // named sets, 0-based nodes
  std::vector<int> node_ids;  // the file's id of each model node (explicit or generated)
  std::map<std::string, std::vector<int>> lines;  // nodes of each named line, start to end
  std::vector<CaseLine> named_lines;  // every named line in the file's order (segments included)
  std::map<std::string, std::vector<int>> element_sets;  // named groups (surfaces, lines), 0-based
  // The water (`water:`, with its waves and current) whose loads act on the model; null for none.
  std::shared_ptr<const hydro::Sea> sea;
  std::optional<SeaOrigin> sea_origin;              // with the sea
  std::shared_ptr<const hydro::Bathymetry> seabed;  // the bed under the water; null for none
  // The seabed's contact with the lines: the index in model->lineLoads() of the one load through
  // which the bed carries the elements of every line; none without seabed contact.
  std::optional<size_t> seabed_contact;
  // The rigid bodies in prescribed motion by name (`histories:` of type rigid_motion, a spread
  // mooring's `platform`): the points they carry follow them, and a host program may drive them
  // (RigidBodyMotion::drive).
  std::map<std::string, std::shared_ptr<model::RigidBodyMotion>> rigid_motions;
  // "FILE:LINE: warning: ..." for what runs but perhaps not as meant (the command prints them).
  std::vector<std::string> warnings;
  // "FILE:LINE: note: ..." for the defaults a run chose that the case does not state (a motion's
  // ramp); the run prints them.
  std::vector<std::string> notes;
};

}  // namespace flexmoor::app
