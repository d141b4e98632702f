// scenario: submerged_tube (apps/case/scenarios/submerged_tube.cpp) against Example 9 written out
// (cases/seed/ex9-submerged-tube.yaml): tests/cases/ex9-scenario.yaml states the same model in
// the scenario's keys. Reference: the explicit case's summary; tolerance 1e-10 relative (the
// explicit file gives the attachment and anchor positions to 12 digits: measured 3.6e-11).
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

TEST(ScenarioSubmergedTube, MatchesTheExplicitModel) {
  const std::string explicit_model = runNamedCase("ex9-submerged-tube");
  const std::string scenario =
      runCaseText("ex9-scenario",
                  readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/tests/cases/ex9-scenario.yaml"));
  double worst = 0.0;
  for (const char* key : {"period_1", "period_2", "period_3", "period_4", "period_5", "period_6",
                          "node1_x_max", "node7_z_max", "mooring_tension_max"}) {
    const double a = summaryValue(scenario, key), b = summaryValue(explicit_model, key);
    worst = std::max(worst, std::abs(a / b - 1.0));
    EXPECT_NEAR(a / b, 1.0, 1e-10) << key << ": " << a << " against " << b;
  }
  std::cout << "largest relative difference " << worst << "\n";
}

}  // namespace
}  // namespace flexmoor::test
