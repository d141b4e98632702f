#pragma once
// A fluid-filled tube built in code for the enclosed-fluid tests: one layer of Q8 membrane
// elements around a horizontal axis (along y), between the symmetry planes y = 0 and y = L, as
// the dissertation models its Example 9. Ring nodes at y = 0 and y = L (2 n each, clockwise from
// the top seen from +y, so the normal y,1 x y,2 points out), the mid-layer nodes at y = L / 2 at
// the element corners' angles. The y dofs are the caller's to fix (the symmetry).
#include <memory>
#include <vector>

#include "libstruct/model/model.hpp"

namespace flexmoor::test {

struct FluidTubeInputs {
  int elements = 6;  // around the circumference
  double radius = 1.0, length = 0.5, centre_z = 0.0;
  double thickness = 0.01, density = 1.0, youngs_modulus = 1.0e6, poisson = 0.3;
};

struct FluidTube {
  std::unique_ptr<model::Model> model;
  std::vector<int> membranes;     // the elements
  std::vector<int> ring0, ring1;  // 2 n nodes each at y = 0 and y = L, ring[0] at the top
  std::vector<int> middle;        // n nodes at y = L / 2, middle[k] at ring index 2 k
};

FluidTube makeFluidTube(const FluidTubeInputs& in);

}  // namespace flexmoor::test
