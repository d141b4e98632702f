// The follower pressure's load stiffness in dynamic steps (DynamicOptions::pressure_load_stiffness):
// the Example 3 tube (quarter model, 4 Q8) inflated suddenly to p = 2 and left to breathe. With the
// load stiffness in the effective tangent the motion is the same (the residual is the same; the
// convergence test is 1e-10) and Newton needs fewer iterations, since the tangent is then exact.
// Reference: the run without it; tolerance 1e-8 of the radial displacement.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/newmark.hpp"
#include "tests/support/membrane_models.hpp"

namespace flexmoor::test {
namespace {

struct Breathing {
  double radial = 0.0;
  int iterations = 0;
};

Breathing breathe(bool load_stiffness) {
  const auto m = quarterTube(TubeInputs{}, 4, 8);
  const model::Assembler a(*m);
  solve::DynamicOptions o;
  o.load_factor = 2.0;
  o.schedule = {{0.05, 40}};
  o.pressure_load_stiffness = load_stiffness;
  o.convergence.displacement_tolerance = 1e-10;
  o.convergence.residual_tolerance = 1e-10;
  model::State s = m->initialState();
  const solve::DynamicReport r = solve::integrate(a, s, o);
  return {s.displacement(0, 0), r.iterations};
}

TEST(DynamicPressureStiffness, SameMotionInFewerIterations) {
  const Breathing without = breathe(false), with = breathe(true);
  ASSERT_GT(std::abs(without.radial), 1e-3);  // it inflated
  EXPECT_NEAR(with.radial, without.radial, 1e-8 * std::abs(without.radial));
  EXPECT_LT(with.iterations, without.iterations);
  std::cout << "iterations: " << without.iterations << " without, " << with.iterations
            << " with the load stiffness; radial displacement " << with.radial << "\n";
}

}  // namespace
}  // namespace flexmoor::test
