#pragma once
// The checks of a built model and its steps that no section of a case file can make alone
// (model_checks.cpp): degenerate elements, free nodes and rigid-body mechanisms, coincident
// nodes, steps that need a mass or more dofs than there are, nodes and bodies below the seabed,
// Morison loads and axial damping on what is not a line. The case reader runs them on what it
// read, buildCase on a case stated in code: both refuse alike. Errors go to the Diagnostics;
// warnings (the model runs, but perhaps not as meant) too, as warnings. They also complete the
// steps: an adaptive step's dt_max, when it has none, bounded by the periods that drive the model.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "apps/case/input/diagnostics.hpp"
#include "apps/problem/case.hpp"
#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/ocean_spec.hpp"

namespace flexmoor::app {

// Where an element comes from, for the messages: the line of the file that defines it (0 for
// none), that item's path ("elements[3]", "lines[1]", "surfaces.roof"; "element 4" in code) and
// its section's name ("" for none).
struct ElementOrigin {
  int line = 0;
  std::string where;
  std::string section;
};

// Where the nodes and elements come from: each element's origin, the line that defines each node
// (0 for none). A case stated in code has no lines (sourceless).
struct ModelOrigins {
  std::vector<ElementOrigin> elements;
  std::vector<int> node_lines;

  // Each element named by its index, at no line.
  static ModelOrigins sourceless(int nodes, int elements);
};

// What the checks read: the case with its built model and steps, the specifications it was built
// from, the origins, the named surfaces and histories (for the messages; either may be empty),
// and where the problems go.
struct CheckedModel {
  Case& c;
  const MeshSpec& mesh;
  const OceanSpec& ocean;
  const ModelOrigins& origins;
  const std::map<std::string, std::vector<int>>& surfaces;
  const std::map<std::string, std::shared_ptr<const model::TimeFunction>>& histories;
  Diagnostics& diag;
  const model::Model& model() const { return *c.model; }
};

void checkModel(const CheckedModel& k);

}  // namespace flexmoor::app
