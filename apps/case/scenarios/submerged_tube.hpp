#pragma once
// scenario: submerged_tube as specifications: a fluid-filled membrane tube with a horizontal axis
// (along y), one layer of Q8 elements between symmetry planes, held under water by a pair of
// mooring cables from the layer's middle to anchors on the bed, under waves; relaxed to
// equilibrium, modes, then a dynamic step. The dissertation's Example 9 is one
// (cases/seed/ex9-submerged-tube.yaml is the same model written out).
//
// The membrane is the surface `tube`; the cables are mooring lines mooring_right and
// mooring_left (anchor: end: their .end, .anchor, on the bed; their .start, .fairlead, at the
// tube), attached at 180 deg +- attach_angle from the top (a multiple of 180 deg / elements
// around, so that an element corner is there) and running `angle` from the vertical outwards down
// to the bed. The liquid fills the tube at the gauge pressure that makes the resultant (liquid
// less sea) at the axis; the sea's incident wave pressure acts on the tube's outside. Every node
// is held in y (the symmetry planes), the anchors in x and z.
//
// The default summary: the periods of modes 1 to 6 of the step `modes`; over the last step, when
// it is dynamic, the largest x of the tube's top (the dissertation's node 1), the largest z of its
// bottom (node 7) and the largest tension of any element; the default figure the x and z of the
// top, bottom, right and left nodes of the ring y = 0 and the first cable element's tension.
#include <vector>

#include "apps/problem/case_spec.hpp"
#include "libhydro/water/water.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"

namespace flexmoor::app {

struct SubmergedTubeSpec {
  UnitSystem units = UnitSystem::SI;
  hydro::Water water;  // its density and depth, and gravity
  // The tube: diameter, depth of its axis, length of the layer (along y), its wall, the elements
  // around it.
  double diameter = 0.0, axis_depth = 0.0, layer = 0.0;
  element::MembraneSection wall;
  int around = 6;
  // The liquid: its density, and the resultant (liquid less sea) pressure at the axis.
  double liquid_density = 0.0, resultant = 0.0;
  // The cables: attached attach_angle from the bottom, `angle` from the vertical (rad); their
  // section and Morison coefficients; elements of `order` nodes.
  double attach_angle = 0.0, angle = 0.0;
  element::CableSection rope;
  LineHydroSpec hydro;
  int elements = 3, order = 3;
};

// The case: the cables, the tube, the supports, gravity, the liquid, the water with the cables'
// Morison loads and the wave pressure on the tube, `steps`, the default summary and figure.
CaseSpec submergedTube(const SubmergedTubeSpec& spec, std::vector<StepSpec> steps);

// Equilibrium by viscous relaxation (Newton from the unstressed membrane has a singular tangent:
// its ovalling is free), to 1e-6, with a damping constant of about twice a cable's axial
// stiffness EA / l, rounded to a power of ten; then the lowest 6 modes about it. Named
// `equilibrium` and `modes`.
StepSpec submergedTubeEquilibrium(const SubmergedTubeSpec& spec);
StepSpec submergedTubeModes();

// The default summary and figure of a submerged tube's case.
std::vector<SummarySpec> submergedTubeSummary(const CaseSpec& c, const SubmergedTubeSpec& spec);
FigureSpec submergedTubeFigure(const CaseSpec& c, const SubmergedTubeSpec& spec);

}  // namespace flexmoor::app
