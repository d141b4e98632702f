#pragma once
// A line that starts on its elastic catenary (a case file's `initial_shape: catenary`), as a
// specification: what the case reader fills from a line's key and a program fills to start a
// mooring line without a case file (case_spec.hpp). startOnCatenaries
// (apps/case/build/build_initial_shape.hpp) puts its nodes there as the model's start.
// Nodes are 0-based model nodes; values are in the case's units.
#include <string>
#include <vector>

#include "libstruct/element/cable_element.hpp"

namespace flexmoor::app {

// A stretch of the line of one section.
struct CatenaryPartSpec {
  std::vector<int> nodes;         // its nodes, start to end
  element::CableSection section;  // its weight per length rho A and its EA
  // The Morison diameter of its elements (OceanSpec::morison), or 0 for none: the water it
  // displaces, and whether it touches the seabed.
  double diameter = 0.0;
};

struct CatenaryStartSpec {
  // The line, or the segments of a multi-segment line start to end, each starting at the last
  // node of the one before.
  std::vector<CatenaryPartSpec> parts;
  double friction = 0.0;    // C_B on the laid part (the static FE has no friction: default 0)
  double max_strain = 0.1;  // hydro::CatenaryLineInputs::max_strain
  int line = 0;             // of the case file that states it (0: none)
  std::string where;        // names it in messages: "lines[2].initial_shape"
};

}  // namespace flexmoor::app
