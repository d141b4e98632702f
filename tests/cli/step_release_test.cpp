// A step's release: lets a held support go. A 10 kg mass on a 1000 N/m spring is held at the
// spring's unstretched length under gravity (10 m/s^2) by a static step, then released by a
// dynamic step: it oscillates about the static deflection m g / k = 0.1 m with that amplitude,
// so half a period (pi / 10 s) later it is at 2 m g / k = 0.2 m below the start. The trapezoidal
// rule's period error at omega dt = 0.0157 moves that by about 1e-10 m: tolerance 1e-7 m. A twin
// oscillator beside it (nodes 3, 4), never held, gives the static step something to solve.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/cli_run.hpp"
#include "tests/support/hanging_masses.hpp"

namespace flexmoor::test {
namespace {

std::string heldMass(const std::string& release) {
  return hangingMassesCase() + R"(  - dynamic: {dt: 0.00157079632679 s, steps: 200)" + release +
         R"(}
summary:
  drop: {quantity: displacement_z, node: 2, scale: -1}
  held_force: {quantity: reaction_z, node: 2, step: 1}
)";
}

TEST(StepRelease, ReleasedMassFallsTwiceTheStaticDeflection) {
  const std::string json =
      runCaseText("release-mass", heldMass(", release: [{node: 2, dofs: [z]}]"));
  EXPECT_NEAR(summaryValue(json, "drop"), 0.2, 1e-7);
  EXPECT_NEAR(summaryValue(json, "held_force"), 100.0, 1e-9);  // m g, while held
}

// The case runs again the same way: the release of one run does not stay in the model.
TEST(StepRelease, WithoutReleaseTheMassStaysHeld) {
  const std::string json = runCaseText("held-mass", heldMass(""));
  EXPECT_NEAR(summaryValue(json, "drop"), 0.0, 1e-12);
}

TEST(StepRelease, ReleasingAFreeDofIsAnError) {
  const auto dir = scratch("release-free");
  const CliRun r = runText(
      dir, "release-free",
      heldMass(", release: [{node: 1, dofs: [z]}, {node: 2, dofs: [z]}, {node: 2, dofs: [z]}]"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.errors.find("node 2 z is not held by a support at this step (got released by an "
                          "earlier step"),
            std::string::npos)
      << r.errors;
}

}  // namespace
}  // namespace flexmoor::test
