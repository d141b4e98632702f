#pragma once
// What holds each group of nodes joined by elements against a rigid translation along x, y and z
// (model_checks.cpp reports the directions nothing holds, at the line that defines the group).
//
// A support on any node of the group holds its direction; a spring or a line to a supported node
// makes that node one of the group's. The steps that need a stiffness are relax, static and modes
// (a dynamic step's inertia, M / (beta h^2) in Newmark's tangent, resists any motion); in each,
// the supports that a release: of it or of an earlier step has let go hold nothing. Loads give a
// rigid group a stiffness in one direction only, the vertical:
//   - the seabed carries a group that its weight in water pulls down onto it (a net downward
//     force: weight, less buoyancy, plus nodal loads) if any of it touches the bed (a line of a
//     section with hydro:, whose diameter is its contact width, or a body);
//   - the water's surface holds a group that its buoyancy lifts up to it if the buoyancy falls as
//     it rises through the surface (a sphere's submerged cap, a line's submerged length);
// and the hoop stiffness of an axisymmetric model holds it radially (x). Nothing holds a group
// horizontally but supports: buoyancy and the bed's contact act vertically, and friction and drag
// act on motion only, not on a displacement.
#include <string>
#include <vector>

#include "apps/case/check/model_checks.hpp"

namespace flexmoor::app {

struct UnrestrainedGroup {
  int root = -1;  // the group's smallest node
  int free = 0;   // the directions nothing holds (bit k: x, y, z)
  // The first step that needs a stiffness in which they are free (an index into c.steps), or -1
  // when only dynamic steps see them free.
  int step = -1;
  bool released = false;   // free there only because a release: let its supports go
  std::string held_other;  // what holds its other directions, if not supports ("" for none)
};

// The groups with a direction nothing holds in some step. root[node] is the smallest node of the
// node's group, for the nodes that elements join (point masses join nothing), and -1 for others.
std::vector<UnrestrainedGroup> unrestrainedGroups(const CheckedModel& k,
                                                  const std::vector<int>& root);

}  // namespace flexmoor::app
