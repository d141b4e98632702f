#pragma once
// The finite-difference check of a surface load's stiffness on one element.
#include "libstruct/element/element.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::test {

// Central differences (step 1e-6) of an element's surface-load forces against its stiffness
// -df/du (element 0 of the context): the largest difference relative to the largest entry.
double surfaceStiffnessError(const element::Element& e, const model::NodalField& X,
                             const model::State& s, const model::SurfaceLoad& load);

}  // namespace flexmoor::test
