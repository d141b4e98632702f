#pragma once
// An elastic catenary line from a raised anchor that lies on a flat, frictionless bed between two
// suspended parts, written for the tests independently of libhydro: each part hangs from its end
// down to a touchdown where it meets the bed tangentially (vertical force 0 there), both with the
// same horizontal force H (nothing on the frictionless laid part changes it), on Irvine's law
// T = EA (stretch - 1). A part of unstretched length s hanging to its touchdown spans
//   x(s) = (H / w) asinh(w s / H) + H s / EA
//   z(s) = (H / w) [sqrt(1 + (w s / H)^2) - 1] + w s^2 / (2 EA)
// (the suspended catenary with V = 0 at its lower end). At a given H the anchor part's length
// s_A solves z(s_A) = h_A (the anchor's height above the bed) and the fairlead part's s_F solves
// z(s_F) = h_F (the fairlead's); the laid rest L - s_A - s_F under tension H stretches by
// H / EA, and H solves x(s_A) + x(s_F) + (L - s_A - s_F)(1 + H / EA) = the horizontal span.
// Roots by GSL's Brent solver (scalar_root.hpp).

namespace flexmoor::test {

struct LaidBetweenInputs {
  double horizontal_span = 0.0;  // anchor to fairlead, along the bed
  double anchor_height = 0.0;    // h_A > 0 above the bed
  double fairlead_height = 0.0;  // h_F > 0 above the bed
  double unstretched_length = 0.0, submerged_weight = 0.0, axial_stiffness = 0.0;
};

struct LaidBetweenSolution {
  double horizontal_force = 0.0;   // H
  double anchor_part = 0.0;        // s_A, unstretched
  double fairlead_part = 0.0;      // s_F, unstretched
  double laid_length = 0.0;        // L - s_A - s_F
  double fairleadTension() const;  // sqrt(H^2 + (w s_F)^2)
  double anchorTension() const;    // sqrt(H^2 + (w s_A)^2)
  double weight = 0.0;
};

// Throws when the line does not lie on the bed between its parts (too taut: it hangs clear; too
// slack: H = 0).
LaidBetweenSolution solveLaidBetween(const LaidBetweenInputs& in);

}  // namespace flexmoor::test
