#pragma once
// Membrane models built in code for the verification tests: the inflated Mooney-Rivlin tube of
// the dissertation's Example 3 (quarter model of quads, or an axisymmetric meridian) and the
// Green & Adkins solution it is checked against.
#include <memory>

#include "libstruct/element/membrane_element.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::test {

// Example 3 (docs/theory.md#example-3): L = 30, R = 10, h0 = 0.01, C1 = 2300, C2 = 280, axial motion
// restrained (plane strain), pressure in the units of C1, C2.
struct TubeInputs {
  double length = 30.0, radius = 10.0, thickness = 0.01, C1 = 2300.0, C2 = 280.0;
};

// Green & Adkins: p = 2 (C1 + C2)(h0 / R)(1 - lambda^-4); returns the hoop stretch lambda.
double tubeStretchAtPressure(const TubeInputs& t, double pressure);

// Quarter of the tube, axis along z, theta from 0 (x axis) to 90 degrees (y axis), `elements`
// quads around the quarter and one along the length; nodes_per_element 4 (Q4) or 8 (Q8).
// Symmetry planes x = 0 and y = 0, every z dof fixed; unit pressure on every element (the load
// factor is the pressure). Node 0 sits on the x axis.
std::unique_ptr<model::Model> quarterTube(const TubeInputs& t, int elements, int nodes_per_element);

// Axisymmetric meridian of the tube along +z at r = R: `elements` elements of `nodes_per_element`
// nodes, y and z fixed, unit pressure. Node 0 is on the meridian.
std::unique_ptr<model::Model> axisymmetricTube(const TubeInputs& t, int elements,
                                               int nodes_per_element);

}  // namespace flexmoor::test
