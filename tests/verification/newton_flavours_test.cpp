// The three Newton flavours of the static solver on one nonlinear problem (Example 3's Q8 tube,
// from its equilibrium at p = 1, found by full Newton, to p = 2, 3, 4; from the unstressed tube
// the first tangent is singular in the tube's inextensional modes and only full Newton recovers,
// as the dissertation found for modified Newton): each converges to the same equilibrium (to the convergence tolerance) and the
// iteration counts per increment are reported. Full Newton converges quadratically, so it needs
// the fewest iterations; BFGS recovers much of what modified Newton loses.
#include <gtest/gtest.h>

#include <iostream>
#include <numeric>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/membrane_models.hpp"

namespace {

using namespace flexmoor;

struct FlavourRun {
  std::vector<int> iterations;
  double radial;
};

FlavourRun run(solve::NewtonFlavour flavour) {
  const test::TubeInputs tube;
  auto m = test::quarterTube(tube, 2, 8);
  model::Assembler assembler(*m);
  model::State s = m->initialState();
  FlavourRun r{};
  solve::StaticOptions first;
  first.pressure_load_stiffness = true;
  solve::solveStatic(assembler, s, first);
  for (int p = 2; p <= 4; ++p) {
    solve::StaticOptions o;
    o.load_factor = p;
    o.flavour = flavour;
    o.stiffness_update = 1000;  // modified and BFGS: tangent only at the start of an increment
    o.max_iterations = 200;
    o.pressure_load_stiffness = true;
    const solve::StaticReport rep = solve::solveStatic(assembler, s, o);
    r.iterations.push_back(rep.increments.front().iterations);
  }
  r.radial = s.displacement(0, 0);
  return r;
}

int total(const FlavourRun& r) {
  return std::accumulate(r.iterations.begin(), r.iterations.end(), 0);
}

TEST(NewtonFlavours, AllReachTheSameEquilibriumWithTheirOwnIterationCounts) {
  const FlavourRun full = run(solve::NewtonFlavour::Full);
  const FlavourRun modified = run(solve::NewtonFlavour::Modified);
  const FlavourRun bfgs = run(solve::NewtonFlavour::Bfgs);
  auto print = [](const char* name, const FlavourRun& r) {
    std::cout << "[ " << name << " ] iterations per increment:";
    for (int i : r.iterations) std::cout << " " << i;
    std::cout << "  (radial displacement at p = 4: " << r.radial << ")\n";
  };
  print("full Newton", full);
  print("modified Newton", modified);
  print("BFGS", bfgs);
  // Same equilibrium: the displacement criterion is 1e-6 relative.
  EXPECT_NEAR(modified.radial, full.radial, 1e-5 * full.radial);
  EXPECT_NEAR(bfgs.radial, full.radial, 1e-5 * full.radial);
  EXPECT_LT(total(full), total(bfgs));
  EXPECT_LT(total(bfgs), total(modified));
}

}  // namespace
