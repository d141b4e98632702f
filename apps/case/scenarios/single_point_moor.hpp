#pragma once
// scenario: single_point_moor as specifications: an anchor, a rope or cable, and a buoy at its
// end, in water; the buoy is held at a given position while viscous relaxation finds the line's
// displaced shape, then released (its support removed: its buoyancy, weight and the line's pull
// act) and the motion integrated in time. The dissertation's Example 8 is one. The model is planar
// (x-z): every node is held in y.
//
// The line is `cable`, a mooring line from the anchor (cable.start, cable.anchor) along +x,
// straight at its unstretched length; the buoy is at its end (cable.end, cable.fairlead), a point
// body with its mass. The default summary: where the buoy ends (buoy_x, buoy_z) and, over a last
// step that is dynamic, its largest speed (buoy_speed_max) and the anchor's largest tension
// (anchor_tension_max); the default figure the four over time.
#include <vector>

#include "apps/problem/case_spec.hpp"
#include "libhydro/loads/point_body.hpp"
#include "libhydro/water/water.hpp"

namespace flexmoor::app {

struct SinglePointMoorSpec {
  UnitSystem units = UnitSystem::SI;
  hydro::Water water;  // its density and depth, and gravity
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  // The line: unstretched length, EA, weight in air per length, Morison coefficients (their
  // diameter the line's), elements of `order` nodes; its law Eq. 2.53's.
  double length = 0.0, ea = 0.0, weight_in_air = 0.0;
  LineHydroSpec hydro;
  int elements = 4, order = 3;
  // The buoy: where it is held, (x, z) from the anchor, its body and its mass.
  double held_x = 0.0, held_z = 0.0;
  hydro::PointBody buoy;
  double buoy_mass = 0.0;
};

// The case: the line, the buoy, the supports (the plane, the anchor, the buoy held), gravity, the
// water with the line's Morison loads and the buoy's, `steps`, the default summary and figure.
CaseSpec singlePointMoor(const SinglePointMoorSpec& spec, std::vector<StepSpec> steps);

// The hold: viscous relaxation (Appendix C) from the straight line, its damping constant a
// hundredth of the line's axial stiffness EA / L, to 1e-6, named `held`.
StepSpec singlePointMoorHold(const SinglePointMoorSpec& spec);
// The release: a dynamic step that lets the buoy (node `buoy`) go in x and z, named `released`;
// its time steps are the caller's.
StepSpec singlePointMoorRelease(int buoy);

// The default summary and figure of a single point mooring's case.
std::vector<SummarySpec> singlePointMoorSummary(const CaseSpec& c);
FigureSpec singlePointMoorFigure(const CaseSpec& c);

}  // namespace flexmoor::app
