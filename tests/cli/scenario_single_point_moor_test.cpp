// scenario: single_point_moor (apps/case/scenarios/single_point_moor.cpp) stands for a model: the
// dissertation's Example 8 by scenario (cases/seed/ex8-relaxation-test.yaml) and written out
// element by element with the numbers the scenario derives (tests/cases/ex8-explicit.yaml) give
// the same summary. Reference: the explicit model; tolerance 1e-12 relative (the same model; only
// the derived numbers' last digit may differ).
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

TEST(ScenarioSinglePointMoor, MatchesTheExplicitModel) {
  const std::string scenario = runNamedCase("ex8-relaxation-test");
  const std::string explicit_model =
      runCaseText("ex8-explicit",
                  readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/tests/cases/ex8-explicit.yaml"));
  for (const char* key : {"buoy_x_t1", "buoy_z_t1", "buoy_x_t3", "buoy_z_t3", "buoy_speed_max",
                          "anchor_tension_max", "held_anchor_tension"}) {
    const double a = summaryValue(scenario, key), b = summaryValue(explicit_model, key);
    EXPECT_NEAR(a / b, 1.0, 1e-12) << key << ": " << a << " against " << b;
  }
}

}  // namespace
}  // namespace flexmoor::test
