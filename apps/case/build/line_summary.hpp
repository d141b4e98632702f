#pragma once
// The length of a named line that lies on the seabed, as a summary quantity (LengthOnSeabed,
// summary_quantities.hpp) resolved from the specifications the line was built from: what a case
// file's `quantity: length_on_seabed, line: NAME` reads to (read_summary.cpp) and what a
// scenario's default summary states (scenarios/).
#include "apps/problem/case_line.hpp"
#include "apps/problem/conditions_spec.hpp"
#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/ocean_spec.hpp"
#include "apps/problem/summary_spec.hpp"

namespace flexmoor::app {

// Fills s with the line's elements and their submerged weight per unstretched length (less the
// water they displace where they have Morison loads), and its anchor: the lower end, when a
// support holds it in z at the bed's level (a raised anchor holds the part hanging from it, and
// its reaction is not the bed's), with the weight of the element there. Returns the index in
// line.elements of the first element that does not sink (s then incomplete, its weight the last
// of s.element_weights), or -1.
int seabedLine(const CaseLine& line, const MeshSpec& mesh, const ConditionsSpec& held,
               const OceanSpec& ocean, SummarySpec& s);

}  // namespace flexmoor::app
