#pragma once
// A quasi-static mooring line between an anchor on a flat, frictionless seabed and a fairlead,
// written independently of flexmoor from the elastic-catenary equations that MAP++ solves
// (Jonkman 2007, "Dynamics modeling and loads analysis of an offshore floating wind turbine",
// NREL/TP-500-41958, section 4.2, with the seabed friction coefficient C_B = 0), Irvine's
// linear law T = EA (stretch - 1):
//  line partly on the seabed (L_B = L - V_F / w > 0):
//    x = L_B + (H / w) asinh(V_F / H) + H L / EA
//    z = (H / w) [sqrt(1 + (V_F / H)^2) - 1] + V_F^2 / (2 EA w)
//  line fully suspended:
//    x = (H / w) [asinh(V_F / H) - asinh((V_F - w L) / H)] + H L / EA
//    z = (H / w) [sqrt(1 + (V_F / H)^2) - sqrt(1 + ((V_F - w L) / H)^2)] + (V_F L - w L^2 / 2) / EA
// x, z: horizontal and vertical fairlead-anchor spans; H, V_F: the fairlead's horizontal and
// vertical force; w: submerged weight per unstretched length.

namespace flexmoor::test {

struct MooringLineInputs {
  double horizontal_span = 0.0, vertical_span = 0.0;
  double unstretched_length = 0.0, submerged_weight = 0.0, axial_stiffness = 0.0;
};

struct MooringLineSolution {
  double horizontal_force = 0.0;   // H, also the anchor's (no friction)
  double fairlead_vertical = 0.0;  // V_F
  double seabed_length = 0.0;      // L_B, 0 when fully suspended
  double fairlead_tension() const;
};

// Newton on (H, V_F) with a finite-difference Jacobian, from a slack-line start; throws when it
// does not converge to 1e-12 of the spans.
MooringLineSolution solveMooringLine(const MooringLineInputs& in);

}  // namespace flexmoor::test
