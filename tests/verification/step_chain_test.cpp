// Chains of analysis steps through the command (`flexmoor run`, the case reader and the runner): a
// run split into several steps must give the result of the same run in one step, to round-off,
// and a load meant to act in a dynamic step acts in it.
//
// Models (SI, every y fixed, so the motion is in the x-z plane):
//  - spring pendulum: a 1 kg point mass on a 1 m spring (k = 200 N/m, carrying compression)
//    pinned at the origin, released at rest from the horizontal, unstretched, under gravity
//    9.81 m/s^2: it swings down and bounces on the spring (a nonlinear motion);
//  - V hanger: a 1 kg point mass at (0, 0, -1 m) hung from two springs (k = 200 N/m, rest length
//    the reference sqrt(2) m) pinned at (-+1 m, 0, 0), under gravity and a 2 N horizontal load
//    (neither has a history, so both scale with the load factor);
//  - falling mass: a 2 kg point mass, x and y fixed, under gravity, on a tension-only spring to a
//    pin 10 m below it: falling towards the pin, the spring is slack, so the fall is free.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

const std::string kPendulum = R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [1 m, 0, 0]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 200 N/m, compression: carry}
  - {type: point_mass, node: 2, mass: 1 kg}
supports:
  - {node: 1, fix: [x, y, z]}
  - {node: 2, fix: [y]}
loads:
  gravity: {g: 9.81 m/s^2}
summary:
  spring_force: {quantity: end_tension, element: 1, end: last}
  x: {quantity: position_x, node: 2}
  z: {quantity: position_z, node: 2}
steps:
)";

const std::string kHanger = R"(units: SI
nodes:
  1: [-1 m, 0, 0]
  2: [1 m, 0, 0]
  3: [0, 0, -1 m]
elements:
  - {type: spring, nodes: [1, 3], stiffness: 200 N/m, compression: carry}
  - {type: spring, nodes: [2, 3], stiffness: 200 N/m, compression: carry}
  - {type: point_mass, node: 3, mass: 1 kg}
supports:
  - {nodes: [1, 2], fix: [x, y, z]}
  - {node: 3, fix: [y]}
loads:
  gravity: {g: 9.81 m/s^2}
  nodal:
    - {node: 3, force: [2 N, 0, 0]}
summary:
  left_force: {quantity: end_tension, element: 1, end: last}
  right_force: {quantity: end_tension, element: 2, end: last}
  x: {quantity: position_x, node: 3}
  z: {quantity: position_z, node: 3}
  settled_z: {quantity: position_z, node: 3, step: settle}
steps:
)";

const std::string kFallingMass = R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [0, 0, -10 m]
elements:
  - {type: point_mass, node: 1, mass: 2 kg}
  - {type: spring, nodes: [2, 1], stiffness: 200 N/m}
supports:
  - {node: 1, fix: [x, y]}
  - {node: 2, fix: [x, y, z]}
loads:
  gravity: {g: 9.81 m/s^2}
summary:
  z: {quantity: displacement_z, node: 1}
steps:
)";

// A dynamic step of `steps` time steps of 0.01 s, with extra keys.
std::string dynamicStep(int steps, const std::string& extra = "") {
  return "  - dynamic: {dt: 0.01 s, steps: " + std::to_string(steps) + extra + "}\n";
}

// A static step to `load_factor` converged far below the default tolerances, so that two static
// solutions from different starts agree to round-off (Newton's last iterate is then exact to
// about the square of the tolerance).
std::string tightStatic(const std::string& load_factor) {
  return "  - static: {name: settle, load_factor: " + load_factor +
         ", tolerance: 1e-12, residual_tolerance: 1e-13}\n";
}

void expectSameSummary(const std::string& one, const std::string& split,
                       const std::vector<std::string>& keys, double tolerance) {
  for (const std::string& key : keys) {
    const double a = summaryValue(one, key), b = summaryValue(split, key);
    ASSERT_TRUE(std::isfinite(a) && std::isfinite(b)) << key << "\n" << one << "\n" << split;
    std::cout << "[ " << key << " ] " << a << " vs " << b << ", relative difference "
              << std::abs(a - b) / std::abs(a) << "\n";
    EXPECT_NEAR(b, a, tolerance * std::abs(a)) << key;
  }
}

// Reference: the same 1 s of the spring pendulum in one dynamic step (100 steps of 0.01 s).
// Split into five consecutive dynamic steps of 20 time steps each, every later step continues
// from the acceleration the previous one accepted, so the runs must agree to round-off.
// A restart of the later steps from an acceleration near zero shows: with the weight given as a
// nodal load under a constant history (as if gravity had no weight in a first dynamic step), the
// five-step chain then ends with a spring force of 8.97 N against 8.21 N (9%). Measured: equal to
// the last bit (0). Tolerance 1e-12 relative: a margin for round-off, not a model difference.
TEST(StepChain, FiveDynamicStepsGiveTheOneStepResult) {
  const std::string one = runCaseText("chain-one", kPendulum + dynamicStep(100));
  std::string five_steps;
  for (int k = 0; k < 5; ++k) five_steps += dynamicStep(20);
  const std::string five = runCaseText("chain-five", kPendulum + five_steps);
  expectSameSummary(one, five, {"spring_force", "x", "z"}, 1e-12);
  // The pendulum has swung through the lower half: not a run that stayed at rest.
  EXPECT_LT(summaryValue(one, "z"), -0.3);
}

// The same with HHT-alpha (-0.1), whose accepted acceleration is not the equilibrium one of the
// state (it balances the alpha-weighted forces of two steps): recomputing it at a restart would
// show here (weight as above: 26.06 N against 26.36 N, 1.1%). Measured:
// equal to the last bit. Tolerance 1e-12 relative.
TEST(StepChain, HhtStepsContinueFromTheAcceptedAcceleration) {
  const std::string hht = ", hht_alpha: -0.1";
  const std::string one = runCaseText("chain-hht-one", kPendulum + dynamicStep(60, hht));
  const std::string three =
      runCaseText("chain-hht-three",
                  kPendulum + dynamicStep(20, hht) + dynamicStep(20, hht) + dynamicStep(20, hht));
  expectSameSummary(one, three, {"spring_force", "x", "z"}, 1e-12);
}

// dynamic -> static -> dynamic. The static step finds the hanger at rest in equilibrium at load
// factor 1, whatever motion the first dynamic step left; the last dynamic step doubles the load
// factor (the mass is dropped under twice its weight and the side load). Reference: the run
// that starts from the same equilibrium, static -> dynamic. The tails must agree to round-off
// (the two static solutions differ by far less than 1e-13, see tightStatic). A static step
// that kept the velocity of the swing would fail it (as would a first step without weight).
// Measured: 3e-16 relative at most. Tolerance 1e-12 relative.
TEST(StepChain, DynamicStaticDynamicGivesTheTailFromEquilibrium) {
  const std::string tail = dynamicStep(60, ", load_factor: 2");
  const std::string chain =
      runCaseText("chain-dsd", kHanger + dynamicStep(37) + tightStatic("1") + tail);
  const std::string reference = runCaseText("chain-sd", kHanger + tightStatic("1") + tail);
  expectSameSummary(reference, chain, {"left_force", "right_force", "x", "z", "settled_z"}, 1e-12);
  // The tail moves: the mass ends 0.084 m below the equilibrium at load factor 1.
  EXPECT_GT(std::abs(summaryValue(reference, "z") - summaryValue(reference, "settled_z")), 0.05);
}

// A dynamic first step holds load factor 1: a free mass released in it falls with g. Newmark's
// average acceleration integrates a constant acceleration exactly, so z(t) = -g t^2 / 2 at
// t = 1 s (100 steps of 0.01 s), -4.905 m, to round-off. At load factor 0 it would stay at z = 0
// (the mass without weight). Measured: exact (-4.905). Tolerance 1e-12 relative.
TEST(StepChain, MassReleasedInAFirstDynamicStepFallsWithG) {
  const std::string json = runCaseText("falling-mass", kFallingMass + dynamicStep(100));
  const double z = summaryValue(json, "z");
  std::cout << "[ falling mass ] z(1 s) = " << z << " m (exact -4.905)\n";
  EXPECT_NEAR(z, -4.905, 1e-12 * 4.905);
}

// An explicit load_factor holds the loads at that factor: 0.5 halves the fall, -4.905 / 2 m.
// Tolerance as above.
TEST(StepChain, DynamicLoadFactorScalesTheLoadsWithoutHistory) {
  const std::string json =
      runCaseText("half-weight", kFallingMass + dynamicStep(100, ", load_factor: 0.5"));
  EXPECT_NEAR(summaryValue(json, "z"), -0.5 * 4.905, 1e-12 * 4.905);
}

}  // namespace
}  // namespace flexmoor::test
