#pragma once
// The liquids that fill membranes (apps/problem/enclosed_fluid_spec.hpp) on a built model.
#include <string>
#include <vector>

#include "apps/problem/case.hpp"
#include "apps/problem/enclosed_fluid_spec.hpp"
#include "apps/problem/spec_error.hpp"

namespace flexmoor::app {

// Why these membranes of the built model cannot hold a liquid, or "" when they can: none named,
// axisymmetric meridians mixed with 3-D membranes, a wall open to it other than in vertical
// planes, no volume enclosed in the reference shape. `where` names the item ("...on: ...").
std::string enclosureProblem(const Case& c, const std::vector<int>& elements,
                             const std::string& where);

// Each liquid whose wall encloses it put on the model (its pressure, its lumped mass as point
// masses after the mesh's elements); the others are errors.
std::vector<SpecError> buildEnclosedFluids(const std::vector<EnclosedFluidSpec>& fluids, Case& c);

}  // namespace flexmoor::app
