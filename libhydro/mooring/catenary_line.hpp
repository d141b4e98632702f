#pragma once
// An elastic catenary mooring line from an anchor to a fairlead, quasi-static, with seabed
// contact and Coulomb friction on the laid part: the two-equation solve of MAP++ (Jonkman 2007,
// NREL/TP-500-41958, sec. 4.2: the suspended and the seabed-contact equations; Irvine's linear law
// T = EA (stretch - 1), w the submerged weight per unstretched length, C_B the seabed friction
// coefficient). In the line's vertical plane, x along the span from the anchor, z up from it.
//
// One segment:
//   fully suspended (V_A = V - w L >= 0, or no seabed):
//     x_F = H/w [asinh(V/H) - asinh(V_A/H)] + H L / EA
//     z_F = H/w [sqrt(1 + (V/H)^2) - sqrt(1 + (V_A/H)^2)] + (V L - w L^2 / 2) / EA
//   partly on the seabed (the anchor on it, L_B = L - V / w > 0):
//     x_F = L_B + H/w asinh(V/H) + H L / EA
//           + C_B w / (2 EA) [-L_B^2 + (L_B - H / (C_B w)) max(L_B - H / (C_B w), 0)]
//     z_F = H/w [sqrt(1 + (V/H)^2) - 1] + V^2 / (2 EA w)
//
// Several segments (chain - wire - chain, each its own L_i, w_i, EA_i, anchor first) joined at
// connection points that may carry a point force F_c (+ up: a buoy's net buoyancy; - down: a clump
// weight; (rho V - m) g for a body of volume V and mass m): H is the same along the line, and the
// vertical force steps down the line from the fairlead's V, by w_i L_i over segment i and up by
// F_c across connection c (the force balance of each piece). Each suspended piece is the first
// pair of equations above with its own top and bottom vertical forces, the spans their sum; the
// laid part runs from the anchor to the first point where that vertical force turns positive (the
// touchdown, inside a segment or at a clump weight resting on the bed), its tension falling from
// H at the touchdown by C_B w_i per length and by C_B N at each clump weight on the bed (N its
// part of the bed's reaction), never below zero. One segment is the case above; the Jacobian is
// the sum of the pieces' (the touchdown's motion cancels between the laid and the hanging part).
//
// A raised anchor (anchor_height > 0 above the flat bed) whose line would hang below the bed lies
// on it between two suspended parts, one hanging from the anchor down to its touchdown and one
// from the fairlead: each meets the bed tangentially (V = 0 there), and the laid part between is
// frictionless (the start takes the equilibrium in which both parts have the same H; friction
// could hold any difference up to C_B times the laid weight, which no static start determines).
// Its solve (raised_anchor_catenary.hpp) is a bisection on H, each part's hanging length given by
// its height above the bed at that H.
//
// The solve is Newton on (H, V) with that analytic Jacobian from Peyrot and Goulois' start (as
// MAP++, with the line's mean submerged weight), safeguarded (H kept positive, backtracking on the
// span residual); should it stall, a nested bisection (V for the vertical span at fixed H, both
// spans monotone) brackets the root and Newton polishes it. Lines that cannot be started throw
// CatenaryError (see solveCatenary()).
#include <stdexcept>
#include <vector>

namespace flexmoor::hydro {

// One segment of a multi-segment line.
struct CatenarySegment {
  double length = 0.0;           // L_i > 0, unstretched
  double weight = 0.0;           // w_i > 0, submerged weight per unstretched length
  double axial_stiffness = 0.0;  // EA_i > 0
};

struct CatenaryLineInputs {
  double horizontal_span = 0.0;     // x_F >= 0, fairlead from anchor along the bed
  double vertical_span = 0.0;       // z_F, fairlead above the anchor
  double unstretched_length = 0.0;  // L > 0          } a line of one segment (ignored when
  double weight = 0.0;              // w > 0          } segments is given)
  double axial_stiffness = 0.0;     // EA > 0         }
  // A line of segments (one or several), the anchor's first, and the point force at each
  // connection point c (between segments c and c + 1, 0-based here; segments.size() - 1 of
  // them, + up). One segment given here is the line of those three.
  std::vector<CatenarySegment> segments;
  std::vector<double> connection_forces;
  bool seabed = true;  // a flat bed carries the line: the anchor on it, or anchor_height below it
  double anchor_height = 0.0;  // the anchor's height above the bed (seabed only), >= 0
  double friction = 0.0;       // C_B >= 0 on the laid part
  // The largest mean strain a taut line may need (chord / L - 1): above it the line is taken as
  // too short for its span (a typo in the length or the anchor, not a line to start from). 10%
  // is past what steel and chain carry and at the limit of synthetic ropes.
  double max_strain = 0.1;
};

class CatenaryError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A point of the solved line at unstretched arc length s from the anchor.
struct CatenaryPoint {
  double x = 0.0, z = 0.0;  // position, from the anchor
  double tension = 0.0;     // T(s) (just above s at a connection point)
};

struct CatenaryLine {
  CatenaryLineInputs inputs;
  std::vector<CatenarySegment> segments;  // the line's segments (one for a one-segment line)
  double horizontal = 0.0;                // H at the fairlead
  double vertical = 0.0;                  // V at the fairlead (upward pull on the line)
  double anchor_horizontal = 0.0;         // H_A = max(H - C_B w L_B, 0): the force on the anchor,
  double anchor_vertical = 0.0;           // V_A = V - w L when suspended, 0 on the bed (upward +)
  double laid_length = 0.0;               // L_B, unstretched length on the seabed
  // The arc length where the laid part starts: 0 from an anchor on the bed; the length hanging
  // from a raised anchor to its touchdown when the line lies on the bed between two hanging parts.
  double laid_from = 0.0;
  int iterations = 0;  // Newton iterations (and bisection steps, if it fell back)

  double length() const;  // the whole unstretched length
  double fairleadTension() const;
  double anchorTension() const;
  CatenaryPoint at(double s) const;  // 0 <= s <= length()
};

// Solves the line, or throws CatenaryError for one that cannot be started: a non-positive or
// non-finite length, weight or stiffness (of any segment), a non-finite connection force or not
// one for each connection, a negative span or friction, no horizontal span (a vertical line), a
// fairlead or anchor below the seabed, a line too short for its span (mean strain above
// max_strain), a line too long for its span on the seabed (x_F <= L - L_s with L_s the length
// hanging straight down at H = 0, from the fairlead and from a raised anchor: it lies slack on the
// bed, H = 0, its shape not determined), and a buoy (F_c > 0) on the laid part or lifting a part
// hanging from the bed (it would lift the line off the bed there: a shape this start does not
// solve).
CatenaryLine solveCatenary(const CatenaryLineInputs& inputs);

}  // namespace flexmoor::hydro
