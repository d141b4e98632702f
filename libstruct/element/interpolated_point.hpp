#pragma once
// The load point at an integration point of an element: position, velocity and acceleration
// interpolated from the nodes with the shape function values N (3 x n nodal matrices times N),
// and the state's time and the element's index.
#include "libstruct/element/element.hpp"

namespace flexmoor::element {

template <class Nodal, class Values>
model::LoadPoint interpolatedPoint(const ElementContext& c, const Nodal& Y, const Nodal& V,
                                   const Nodal& A, const Values& N) {
  model::LoadPoint point;
  point.position = Y * N;
  point.velocity = V * N;
  point.acceleration = A * N;
  point.time = c.state.time;
  point.still = c.state.still;
  point.element = c.index;
  return point;
}

}  // namespace flexmoor::element
