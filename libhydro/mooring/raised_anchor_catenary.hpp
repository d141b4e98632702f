#pragma once
// A line from a raised anchor (CatenaryLineInputs::anchor_height = h_A > 0 above a flat bed)
// whose catenary would dip below the bed: it lies on the bed between two suspended parts. The
// anchor part [0, s_1] hangs from the anchor down to its touchdown at s_1, the fairlead part
// [s_2, L] from the fairlead down to its touchdown at s_2; each meets the bed tangentially (the
// vertical force V = 0 at its touchdown: the bed carries the weight between), and the laid part
// [s_1, s_2] is frictionless, so that both parts have the same horizontal force H and the laid
// part's tension is H, stretching it by H (s_2 - s_1) / EA.
//
// At a given H, each part's length follows from its height above the bed: the anchor part's drop
// z(0) - z(s_1) = h_A and the fairlead part's rise z(L) - z(s_2) = h_A + z_F, each the suspended
// equations of catenary_line.hpp over its pieces with V = 0 at its touchdown (both grow with the
// part's length). The horizontal span x_A(H) + (s_2 - s_1)(1 + H / EA) + x_F(H) grows with H
// from the slack limit H -> 0 (the parts hanging straight down, the rest laid with no tension)
// to the H at which s_1 = s_2 (the line touching the bed at one point): a bisection on H between
// them solves the line. A span beyond that limit is a line that hangs clear of the bed (the
// suspended equations), one below the slack limit a line too long for its span.
#include <optional>

#include "libhydro/mooring/catenary_line.hpp"
#include "libhydro/mooring/catenary_pieces.hpp"

namespace flexmoor::hydro::catenary_detail {

// The line laid between its hanging parts, or nullopt when it hangs clear of the bed. Throws
// CatenaryError for a line that would lie slack on the bed, or a buoy on the laid part or one
// that would lift a hanging part below its touchdown.
std::optional<CatenaryLine> solveLaidBetweenHangingParts(const Line& l);

// The point at arc length s of a line solveLaidBetweenHangingParts solved.
CatenaryPoint pointLaidBetweenHangingParts(const Line& l, const CatenaryLine& line, double s);

}  // namespace flexmoor::hydro::catenary_detail
