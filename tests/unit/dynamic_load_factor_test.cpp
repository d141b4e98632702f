// The load factor a dynamic step holds, as the reader sets it: `load_factor` when given; else the
// factor the previous step left (unset: the state's), or 1 when no earlier step sets one (modes
// steps do not), so that gravity acts in a dynamic step that starts a run.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

std::string withSteps(const std::string& steps) {
  return R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [1, 0, 0]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 200}
  - {type: point_mass, node: 2, mass: 1}
supports:
  - {node: 1, fix: [x, y, z]}
loads:
  gravity: {g: 9.81}
steps:
)" + steps;
}

std::optional<double> held(const Case& c, int step) { return c.steps[step].dynamic.load_factor; }

TEST(DynamicLoadFactor, DefaultsToOneAtTheStartOfARunAndToThePreviousFactorAfter) {
  const Case c = readCase(test::writeCase("dynamic-factors.yaml", withSteps(R"(
  - modes: {count: 1}
  - dynamic: {dt: 0.01, steps: 1}
  - static: {load_factor: 0.5}
  - dynamic: {dt: 0.01, steps: 1}
  - dynamic: {dt: 0.01, steps: 1, load_factor: 2}
  - dynamic: {dt: 0.01, steps: 1}
)")));
  EXPECT_EQ(held(c, 1), std::optional<double>(1.0));  // only a modes step before it
  EXPECT_EQ(held(c, 3), std::nullopt);                // keeps the static step's 0.5
  EXPECT_EQ(held(c, 4), std::optional<double>(2.0));
  EXPECT_EQ(held(c, 5), std::nullopt);  // keeps 2
}

TEST(DynamicLoadFactor, AWrongValueIsReportedWithItsLine) {
  const auto m = test::problems(test::writeCase("dynamic-bad-factor.yaml", withSteps(R"(
  - dynamic: {dt: 0.01, steps: 1, load_factor: 2 m}
)")));
  EXPECT_TRUE(test::anyContains(m, "dynamic-bad-factor.yaml:14: steps[1].dynamic.load_factor: wrong unit"))
      << test::joined(m);
}

}  // namespace
}  // namespace flexmoor::app
