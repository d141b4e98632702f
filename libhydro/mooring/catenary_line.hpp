#pragma once
// One elastic catenary mooring line from an anchor to a fairlead, quasi-static, with seabed
// contact and Coulomb friction on the laid part: the two-equation solve of MAP++ (Jonkman 2007,
// NREL/TP-500-41958, sec. 4.2: the suspended and the seabed-contact equations; Irvine's linear law
// T = EA (stretch - 1), w the submerged weight per unstretched length, C_B the seabed friction
// coefficient). In the line's vertical plane, x along the span from the anchor, z up from it.
//
//   fully suspended (V_A = V - w L >= 0, or no seabed):
//     x_F = H/w [asinh(V/H) - asinh(V_A/H)] + H L / EA
//     z_F = H/w [sqrt(1 + (V/H)^2) - sqrt(1 + (V_A/H)^2)] + (V L - w L^2 / 2) / EA
//   partly on the seabed (the anchor on it, L_B = L - V / w > 0):
//     x_F = L_B + H/w asinh(V/H) + H L / EA
//           + C_B w / (2 EA) [-L_B^2 + (L_B - H / (C_B w)) max(L_B - H / (C_B w), 0)]
//     z_F = H/w [sqrt(1 + (V/H)^2) - 1] + V^2 / (2 EA w)
//
// The solve is Newton on (H, V) with the analytic Jacobian from Peyrot and Goulois' start (as
// MAP++), safeguarded (H kept positive, backtracking on the span residual); should it stall, a
// nested bisection (V for the vertical span at fixed H, both spans monotone) brackets the root
// and Newton polishes it. Lines that cannot be started throw CatenaryError (see solve()).
#include <stdexcept>

namespace flexmoor::hydro {

struct CatenaryLineInputs {
  double horizontal_span = 0.0;     // x_F >= 0, fairlead from anchor along the bed
  double vertical_span = 0.0;       // z_F, fairlead above the anchor
  double unstretched_length = 0.0;  // L > 0
  double weight = 0.0;              // w > 0, submerged weight per unstretched length
  double axial_stiffness = 0.0;     // EA > 0
  bool seabed = true;               // the anchor lies on a flat bed that carries the line
  double friction = 0.0;            // C_B >= 0 on the laid part
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
  double tension = 0.0;     // T(s)
};

struct CatenaryLine {
  CatenaryLineInputs inputs;
  double horizontal = 0.0;         // H at the fairlead
  double vertical = 0.0;           // V at the fairlead (upward pull on the line)
  double anchor_horizontal = 0.0;  // H_A = max(H - C_B w L_B, 0): the force on the anchor,
  double anchor_vertical = 0.0;    // V_A = V - w L when suspended, 0 on the bed (upward +)
  double laid_length = 0.0;        // L_B, unstretched length on the seabed
  int iterations = 0;              // Newton iterations (and bisection steps, if it fell back)

  double fairleadTension() const;
  double anchorTension() const;
  CatenaryPoint at(double s) const;  // 0 <= s <= L
};

// Solves the line, or throws CatenaryError for one that cannot be started: a non-positive or
// non-finite length, weight or stiffness, a negative span or friction, no horizontal span (a
// vertical line), a fairlead below the seabed, a line too short for its span (mean strain above
// max_strain), and a line too long for its span on the seabed (x_F <= L - L_s with L_s the length
// hanging straight down at H = 0: it lies slack on the bed, H = 0, its shape not determined).
CatenaryLine solveCatenary(const CatenaryLineInputs& inputs);

}  // namespace flexmoor::hydro
