// summary: quantities taken over a dynamic step's time (at:, stat:, window:) as the reader keeps
// them: times converted to seconds and checked against the step's span in the run's time, which
// each dynamic step advances by its duration and the other steps keep.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

// A static step, a dynamic step of 0.4 s (0 to 0.4 s), a modes step and a dynamic step of 0.2 s
// (0.4 to 0.6 s), then the summary lines given.
std::string twoDynamicSteps(const std::string& summary) {
  return R"(units: US
materials:
  steel: {type: linear_elastic, E: 4.2e9 psf}
sections:
  wire: {material: steel, area: 1.0e-3 ft^2, density: 15 slug/ft^3}
lines:
  - {name: cable, from: [0, 0, 0], to: [30 ft, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.03 ft, 0, 0]}
  - {nodes: cable, fix: [y]}
steps:
  - static: {name: pretension}
  - dynamic: {name: first, schedule: [{dt: 0.005 s, steps: 40}, {dt: 0.01 s, steps: 20}]}
  - modes: {name: modes, count: 2}
  - dynamic: {name: second, dt: 10 ms, steps: 20}
summary:
)" + summary;
}

const SummarySpec& spec(const Case& c, const std::string& name) {
  for (const SummarySpec& s : c.summary)
    if (s.name == name) return s;
  throw std::runtime_error("no summary quantity " + name);
}

TEST(CaseReaderSummaryTime, TimesAndWindowsAreReadInTheRunsTime) {
  const Case c = readCase(test::writeCase("summary-time.yaml", twoDynamicSteps(R"(
  at_half: {quantity: position_z, node: cable.middle, at: 500 ms}
  speed_max: {quantity: speed, node: cable.middle, stat: max, step: first}
  late_std: {quantity: velocity_z, node: cable.middle, stat: std, window: {from: 450 ms}}
  mid_mean: {quantity: end_tension, element: 1, end: last, stat: mean, step: 2,
             window: {from: 0.1 s, to: 0.3 s}}
  end: {quantity: displacement_z, node: cable.middle}
)")));
  using R = SummarySpec::Reduction;
  const SummarySpec& at = spec(c, "at_half");
  EXPECT_EQ(at.reduction, R::AtTime);
  EXPECT_DOUBLE_EQ(at.at, 0.5);
  EXPECT_EQ(at.step, -1);  // the last step, `second`
  const SummarySpec& speed = spec(c, "speed_max");
  EXPECT_EQ(speed.reduction, R::Max);
  EXPECT_EQ(speed.step, 1);
  EXPECT_EQ(speed.unit, "ft/s");
  EXPECT_TRUE(std::isinf(speed.from) && speed.from < 0);  // the whole step
  EXPECT_TRUE(std::isinf(speed.to) && speed.to > 0);
  const SummarySpec& late = spec(c, "late_std");
  EXPECT_EQ(late.reduction, R::Std);
  EXPECT_EQ(late.quantity, SummarySpec::Quantity::Velocity);
  EXPECT_EQ(late.component, 2);
  EXPECT_DOUBLE_EQ(late.from, 0.45);
  EXPECT_TRUE(std::isinf(late.to));
  const SummarySpec& mean = spec(c, "mid_mean");
  EXPECT_EQ(mean.reduction, R::Mean);
  EXPECT_DOUBLE_EQ(mean.from, 0.1);
  EXPECT_DOUBLE_EQ(mean.to, 0.3);
  EXPECT_EQ(spec(c, "end").reduction, R::StepEnd);
}

// The second dynamic step spans 0.4 to 0.6 s: a time inside the first one is outside it.
TEST(CaseReaderSummaryTime, ALaterDynamicStepStartsWhereTheEarlierOnesEnd) {
  const auto messages =
      test::problems(test::writeCase("summary-time-early.yaml", twoDynamicSteps(R"(
  early: {quantity: position_z, node: cable.middle, at: 0.3 s}
  late: {quantity: speed, node: cable.middle, stat: mean, step: second, window: {to: 0.7 s}}
)")));
  EXPECT_TRUE(test::anyContains(messages,
                                ":19: summary.early.at: outside the step (got 0.3 s, "
                                "expected 0.4 to 0.6 s, the time span of step "
                                "'second')"))
      << test::joined(messages);
  EXPECT_TRUE(test::anyContains(messages,
                                ":20: summary.late.window.to: outside the step "
                                "(got 0.7 s, expected 0.4 to 0.6 s"))
      << test::joined(messages);
  EXPECT_EQ(messages.size(), 2u) << test::joined(messages);
}

}  // namespace
}  // namespace flexmoor::app
