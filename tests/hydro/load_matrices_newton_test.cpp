// What the motion-dependent loads' matrices are worth to Newton in a time step: a line pinned at
// both ends 10 m down in 30 m of water, in a 2 m, 6 s Airy wave, integrated by Newmark at
// dt = 0.05 s with the Morison load's stiffness, drag damping and added mass in the effective
// tangent (DynamicOptions::load_matrices = Step, the default) and without them (Off: their forces
// stay in the residual only, so Newton iterates on the added mass as on a fixed point whose
// contraction is M_L / (M + K dt^2 beta)).
// Up to 100 Newton iterations a step, so that Off's slow convergence is counted, not cut.
//  - A line of density 2050 kg/m^3 (added mass half its own mass): Off converges, slowly; Step
//    must cut the iterations per step at least fivefold (measured 4.63 against 50.0, which
//    also needed 2 step cuts: 10.8).
//  - A buoyant rope of density 910 kg/m^3 (added mass 1.13 times its own): Off's fixed point
//    diverges, and halving the step does not help (the contraction tends to M_L / M > 1); the run
//    fails with a ConvergenceError, while Step integrates it without a cut (measured 4.6
//    iterations a step; asserted below 6).
// Also the cost of updating the matrices at every iteration (Iteration) against once per step,
// printed (not asserted: no timed tests; docs/performance.md has the figures).
#include <gtest/gtest.h>

#include <ctime>
#include <iostream>

#include "libstruct/solve/newmark.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "tests/support/cable_models.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;
using Update = solve::DynamicOptions::LoadMatrixUpdate;

constexpr double kDepth = 30.0;

OceanLine lineInAWave(double density, int elements) {
  OceanLineInputs in;
  in.start = Vector3d(0.0, 0.0, -10.0);
  in.end = Vector3d(20.0, 0.0, -10.0);
  in.elements = elements;
  in.nodes_per_element = 3;
  in.youngs_modulus = 1.0e9;
  in.density = density;
  in.morison.diameter = 0.04;
  in.morison.cn = 1.2;
  in.morison.ct = 0.01;
  in.morison.ca = 1.0;
  in.morison.ca_axial = 0.1;
  const auto sea = stillWater(kDepth);
  sea->addComponent(
      hydro::WaveComponent::fromHeightAndPeriod(2.0, 6.0, 0.0, 0.0, kDepth, kStandardGravity));
  in.sea = sea;
  OceanLine line = makeOceanLine(in);
  line.model->setGravity(Vector3d(0.0, 0.0, -kStandardGravity));
  pin(*line.model, line.nodes.front());
  pin(*line.model, line.nodes.back());
  line.model->numberEquations();
  return line;
}

solve::DynamicReport run(const OceanLine& line, Update update, int steps) {
  const model::Assembler assembler(*line.model);
  solve::DynamicOptions options;
  options.schedule = {{0.05, steps}};
  options.load_factor = 1.0;
  options.load_matrices = update;
  options.max_iterations = 100;
  model::State s = line.model->initialState();
  return solve::integrate(assembler, s, options);
}

double iterationsPerStep(const solve::DynamicReport& r) {
  return static_cast<double>(r.iterations) / r.steps;
}

TEST(LoadMatricesNewton, TheyCutTheIterationsPerStepOfALineInAWave) {
  const OceanLine line = lineInAWave(2050.0, 5);
  const solve::DynamicReport with = run(line, Update::Step, 60);
  const solve::DynamicReport without = run(line, Update::Off, 60);
  std::cout << "line in a wave, dt 0.05 s, 60 steps: Step " << iterationsPerStep(with)
            << " iterations/step (" << with.cuts << " cuts), Off " << iterationsPerStep(without)
            << " iterations/step (" << without.cuts << " cuts)\n";
  EXPECT_EQ(with.cuts, 0);
  EXPECT_LT(5.0 * iterationsPerStep(with), iterationsPerStep(without));
}

// A rope barely denser than water (910 kg/m^3 against 1025: its added mass is most of its
// inertia): without the matrices each full Newton increment overshoots, and only the backtracking
// of the increments that raise the residual carries it; with them Newton converges in a few
// iterations. Measured: Step 3.8 iterations a step, no backtrack; Off 12.2, with backtracks.
// Tolerance: Off at least 2.5 times the iterations of Step.
TEST(LoadMatricesNewton, WithoutThemABuoyantRopeNeedsBacktrackingAndThriceTheIterations) {
  const OceanLine rope = lineInAWave(910.0, 5);
  const solve::DynamicReport with = run(rope, Update::Step, 60);
  const solve::DynamicReport without = run(rope, Update::Off, 60);
  std::cout << "buoyant rope, dt 0.05 s, 60 steps: Step " << iterationsPerStep(with)
            << " iterations/step (" << with.backtracks << " backtracks, " << with.cuts
            << " cuts), Off " << iterationsPerStep(without) << " iterations/step ("
            << without.backtracks << " backtracks, " << without.cuts << " cuts)\n";
  EXPECT_EQ(with.cuts, 0);
  EXPECT_EQ(with.backtracks, 0);
  EXPECT_LT(iterationsPerStep(with), 6.0);
  EXPECT_GT(without.backtracks, 0);
  EXPECT_GT(iterationsPerStep(without), 2.5 * iterationsPerStep(with));
}

// The cost of the two update policies on a longer line (20 elements, 200 steps): printed only.
TEST(LoadMatricesNewton, CostOfUpdatingThemPerStepOrPerIteration) {
  const OceanLine line = lineInAWave(2050.0, 20);
  for (const Update update : {Update::Step, Update::Iteration}) {
    const std::clock_t start = std::clock();
    const solve::DynamicReport r = run(line, update, 200);
    const double cpu = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    std::cout << (update == Update::Step ? "Step" : "Iteration") << ": " << cpu << " s CPU, "
              << r.iterations << " iterations in " << r.steps << " steps, " << r.load_matrix_updates
              << " load-matrix updates, " << r.tangent_updates << " factorisations\n";
    EXPECT_EQ(r.cuts, 0);
  }
}

}  // namespace
}  // namespace flexmoor::test
