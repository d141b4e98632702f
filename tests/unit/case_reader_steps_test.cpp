// The case-file reader's analysis steps: static (load or arc-length control, Newton, modified
// Newton, BFGS), modes and dynamic steps map onto the solver options, and their mistakes are
// reported with their lines.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

using test::anyContains;
using test::joined;
using test::problems;
using test::writeCase;

// A taut cable of 4 elements, then `steps` and `summary`.
std::string cableCase(const std::string& steps, const std::string& summary = "") {
  return R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4, density: 7850}
lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01, 0, 0]}
  - {nodes: cable, fix: [y]}
steps:
)" + steps +
         (summary.empty() ? "" : "summary:\n" + summary);
}

TEST(CaseReaderSteps, StaticArcLengthAndNewtonOptions) {
  const Case c = readCase(writeCase(
      "arc.yaml",
      cableCase(
          R"(  - static: {name: up, load_factor: 2, increments: 4, control: arc_length, psi: 0.5,
               desired_iterations: 6, max_increments: 300, newton: full, max_iterations: 40,
               tolerance: 1e-7, criterion: both, pressure_stiffness: true}
)")));
  ASSERT_EQ(c.steps.size(), 1u);
  const solve::StaticOptions& o = c.steps[0].statics;
  EXPECT_EQ(c.steps[0].name, "up");
  EXPECT_EQ(o.control, solve::LoadControl::ArcLength);
  EXPECT_DOUBLE_EQ(o.load_factor, 2.0);
  EXPECT_EQ(o.increments, 4);
  EXPECT_DOUBLE_EQ(o.arc.psi, 0.5);
  EXPECT_EQ(o.arc.desired_iterations, 6);
  EXPECT_EQ(o.arc.max_increments, 300);
  EXPECT_EQ(o.flavour, solve::NewtonFlavour::Full);
  EXPECT_EQ(o.max_iterations, 40);
  EXPECT_DOUBLE_EQ(o.convergence.displacement_tolerance, 1e-7);
  EXPECT_TRUE(o.convergence.use_displacement && o.convergence.use_residual);
  EXPECT_TRUE(o.pressure_load_stiffness);
}

TEST(CaseReaderSteps, ModesAndDynamicOptions) {
  const Case c = readCase(
      writeCase("dynamic.yaml", cableCase(R"(  - static: {name: pretension}
  - modes: {name: about, count: 6, shift: 2 Hz, mass: lumped}
  - dynamic: {schedule: [{dt: 0.02 s, steps: 50}, {dt: 0.05 s, steps: 10}], hht_alpha: -0.1,
              newton: modified, stiffness_update: 3, rayleigh: {mass: 0.1, stiffness: 0.001 s},
              max_step_cuts: 4, output_every: 5}
  - dynamic: {dt: 0.01, steps: 7, gamma: 0.6, beta: 0.3025}
)",
                                          R"(  omega_2: {quantity: frequency, mode: 2, step: about}
)")));
  ASSERT_EQ(c.steps.size(), 4u);
  const solve::ModalOptions& m = c.steps[1].modes;
  EXPECT_EQ(m.modes, 6);
  EXPECT_NEAR(m.shift, std::pow(4.0 * M_PI, 2), 1e-9);  // 2 Hz is omega = 4 pi rad/s
  EXPECT_EQ(m.mass, element::MassKind::Lumped);
  const solve::DynamicOptions& d = c.steps[2].dynamic;
  ASSERT_EQ(d.schedule.size(), 2u);
  EXPECT_DOUBLE_EQ(d.schedule[0].dt, 0.02);
  EXPECT_EQ(d.schedule[0].steps, 50);
  EXPECT_DOUBLE_EQ(d.schedule[1].dt, 0.05);
  EXPECT_DOUBLE_EQ(d.hht_alpha, -0.1);
  EXPECT_EQ(d.flavour, solve::NewtonFlavour::Modified);
  EXPECT_EQ(d.stiffness_update, 3);
  EXPECT_DOUBLE_EQ(d.rayleigh_mass, 0.1);
  EXPECT_DOUBLE_EQ(d.rayleigh_stiffness, 0.001);
  EXPECT_EQ(d.max_step_cuts, 4);
  EXPECT_EQ(c.steps[2].output_every, 5);
  const solve::DynamicOptions& e = c.steps[3].dynamic;
  ASSERT_EQ(e.schedule.size(), 1u);
  EXPECT_EQ(e.schedule[0].steps, 7);
  EXPECT_DOUBLE_EQ(e.gamma, 0.6);
  EXPECT_DOUBLE_EQ(e.beta, 0.3025);
  ASSERT_EQ(c.summary.size(), 1u);
  EXPECT_EQ(c.summary[0].quantity, SummarySpec::Quantity::Frequency);
  EXPECT_EQ(c.summary[0].mode, 2);
  EXPECT_EQ(c.summary[0].step, 1);
  EXPECT_EQ(c.summary[0].unit, "rad/s");
}

// A dynamic step's time: duration alone is adaptive (records every output, default a thousandth
// of the duration; dt_max a tenth of the shortest forcing period unless given), dt with duration
// fixed steps, and output a whole number of them.
TEST(CaseReaderSteps, DynamicTimeIsAdaptiveOrFixed) {
  const Case c = readCase(writeCase("time.yaml", cableCase(R"(  - dynamic: {duration: 2 s}
  - dynamic: {duration: 600 s, output: 0.1 s, step_tolerance: 1e-3, dt_max: 0.5 s, dt_min: 1e-4 s}
  - dynamic: {dt: 0.05 s, duration: 3 s, output: 0.25 s}
)")));
  ASSERT_EQ(c.steps.size(), 3u);
  ASSERT_TRUE(c.steps[0].adaptive());
  const solve::AdaptiveSteps& a = *c.steps[0].dynamic.adaptive;
  EXPECT_DOUBLE_EQ(a.duration, 2.0);
  EXPECT_DOUBLE_EQ(a.tolerance, 0.01);
  EXPECT_DOUBLE_EQ(c.steps[0].output_interval, 2e-3);
  EXPECT_DOUBLE_EQ(c.steps[0].duration(), 2.0);
  EXPECT_EQ(c.steps[0].streamedRecords(), 1000);
  const solve::AdaptiveSteps& b = *c.steps[1].dynamic.adaptive;
  EXPECT_DOUBLE_EQ(b.tolerance, 1e-3);
  EXPECT_DOUBLE_EQ(b.dt_max, 0.5);
  EXPECT_DOUBLE_EQ(b.dt_min, 1e-4);
  EXPECT_DOUBLE_EQ(c.steps[1].output_interval, 0.1);
  EXPECT_FALSE(c.steps[2].adaptive());
  ASSERT_EQ(c.steps[2].dynamic.schedule.size(), 1u);
  EXPECT_EQ(c.steps[2].dynamic.schedule[0].steps, 60);
  EXPECT_EQ(c.steps[2].output_every, 5);
}

TEST(CaseReaderSteps, StepMistakesAreReportedWithTheirLines) {
  const std::vector<std::string> m = problems(
      writeCase("bad-steps.yaml", cableCase(R"(  - static: {psi: 0.5}
  - modes: {count: 3}
  - dynamic: {dt: 0.1, steps: 10, schedule: [{dt: 0.1, steps: 2}]}
  - dynamic: {dt: 0.1, steps: 10, gamma: 0.4, hht_alpha: -0.5}
  - dynamic: {dt: 0.1, steps: 10, beta: 0.3, hht_alpha: -0.1, newton: bfgs}
  - dynamic: {}
  - relax: {}
  - vibrate: {}
  - static: {control: arc_length, newton: self_corrective}
)",
                                            R"(  too_high: {quantity: frequency, mode: 4, step: 2}
  not_modes: {quantity: frequency, mode: 1}
  tension: {quantity: resultant_max, element: 1}
)")));
  EXPECT_TRUE(anyContains(m,
                          "bad-steps.yaml:13: steps[1].static.psi: only used with control: "
                          "arc_length (got no control: key)"))
      << joined(m);
  EXPECT_TRUE(anyContains(
      m, "bad-steps.yaml:15: steps[3].dynamic.schedule: given with dt (expected either"))
      << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "bad-steps.yaml:16: steps[4].dynamic.gamma: out of range (got 0.4, "
                          "expected 0.5 to 1)"))
      << joined(m);
  EXPECT_TRUE(
      anyContains(m, "steps[4].dynamic.hht_alpha: out of range (got -0.5, expected -1/3 to 0)"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "bad-steps.yaml:17: steps[5].dynamic.hht_alpha: given with beta"))
      << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "steps[5].dynamic.newton: unknown value (got 'bfgs', expected one "
                          "of: full, modified, self_corrective)"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "bad-steps.yaml:18: steps[6].dynamic: missing key 'duration'"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "bad-steps.yaml:20: steps[8]: not a step (got 'vibrate'"))
      << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "bad-steps.yaml:21: steps[9].static.newton: arc length iterates with "
                          "full Newton (got self_corrective"))
      << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "summary.too_high.mode: beyond the modes computed (got 4, expected 1 "
                          "to 3"))
      << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "summary.not_modes.quantity: frequency of a step that is not a "
                          "modes step"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "summary.tension.element: element 1 is a cable (expected a membrane)"))
      << joined(m);
}

}  // namespace
}  // namespace flexmoor::app
