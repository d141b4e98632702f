// A case run in process (apps/run/simulation.hpp) with an in-memory sink: the records are the
// ones the command streams to netCDF (one closing the relaxation, then one per accepted time step
// of Example 8), the summary is the command's, and the same Case runs again to the same numbers
// (a step's release of the buoy is undone when a run ends). Reference: the command's own run of
// the case (flexmoor run); tolerance 0, the same code on the same input.
//
// Records streamed through a BackgroundSink have their element results and reactions computed
// on its thread from the inputs the run's thread took (ResultFrame::pending): they must be the
// records computed on the run's thread, exactly (the same kernel on the same numbers), for lines
// under water loads and gravity (Example 8), membranes under sea pressure with cables (Example
// 9) and cables with internal damping (the demo with a damping ratio).
#include "apps/run/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include "apps/case/case_reader.hpp"
#include "apps/output/background_sink.hpp"
#include "apps/output/memory_sink.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

app::SimulationResult runInProcess(const app::Case& c, app::ResultSink& sink) {
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  simulation.addSink(sink);
  return simulation.run();
}

// The case's records as the run's thread computes them and as the BackgroundSink's thread does.
void expectSameRecordsOnTheWritingThread(const app::Case& c, size_t least_records) {
  app::MemorySink direct, behind;
  ASSERT_EQ(runInProcess(c, direct).exit_code, app::kSuccess);
  {
    app::BackgroundSink background(behind);
    ASSERT_EQ(runInProcess(c, background).exit_code, app::kSuccess);
  }
  const std::vector<app::ResultFrame>& a = direct.frames();
  const std::vector<app::ResultFrame>& b = behind.frames();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), least_records);
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(b[k].pending, nullptr) << k;
    EXPECT_EQ(a[k].state->displacement, b[k].state->displacement) << k;
    EXPECT_EQ(a[k].reactions, b[k].reactions) << k;
    ASSERT_EQ(a[k].elements.size(), b[k].elements.size()) << k;
    for (size_t e = 0; e < a[k].elements.size(); ++e) {
      const element::ElementResult &x = a[k].elements[e], &y = b[k].elements[e];
      EXPECT_EQ(x.point_tension, y.point_tension) << k << " " << e;
      EXPECT_EQ(x.end_tension[0], y.end_tension[0]) << k << " " << e;
      EXPECT_EQ(x.end_tension[1], y.end_tension[1]) << k << " " << e;
      ASSERT_EQ(x.point_resultant.size(), y.point_resultant.size());
      for (size_t q = 0; q < x.point_resultant.size(); ++q)
        EXPECT_EQ(x.point_resultant[q], y.point_resultant[q]) << k << " " << e << " " << q;
    }
  }
}

TEST(Simulation, RunsACaseInProcessAsTheCommandDoes) {
  const app::Case c = app::readCase(app::resolveCasePath("ex8-relaxation-test"));
  app::MemorySink first, second;
  const app::SimulationResult a = runInProcess(c, first);
  ASSERT_EQ(a.exit_code, app::kSuccess);
  // The held state (a stage record), the release's first state and its 600 time steps.
  ASSERT_EQ(first.frames().size(), 602u);
  EXPECT_EQ(first.frames().front().step_name, "held");
  EXPECT_TRUE(first.frames().front().stage);
  EXPECT_EQ(first.frames()[1].step_name, "released");
  EXPECT_FALSE(first.frames()[1].stage);
  EXPECT_EQ(first.frames()[1].state->time, 0.0);
  EXPECT_NEAR(first.frames().back().state->time, 3.0, 1e-12);
  const std::string json = runNamedCase("ex8-relaxation-test");
  for (const auto& [name, value] : a.summary) EXPECT_EQ(value, summaryValue(json, name)) << name;

  const app::SimulationResult b = runInProcess(c, second);
  ASSERT_EQ(b.summary.size(), a.summary.size());
  for (size_t k = 0; k < a.summary.size(); ++k)
    EXPECT_EQ(b.summary[k].second, a.summary[k].second) << a.summary[k].first;
}

// A record's time is its schedule's, exactly: the demo's 40 steps of 0.005 s (every fourth
// written) end at k 0.005 s and its 20 steps of 0.01 s at 0.2 s + k 0.01 s, each the product
// computed once, not a sum of steps (whose round-off put 5,982 of OC4's 6,001 times off the 0.1 s
// grid, so that xarray's ds.sel(time=2.5) found nothing).
TEST(Simulation, RecordTimesAreTheSchedulesExactly) {
  const app::Case c = app::readCase(app::resolveCasePath("driven-taut-cable"));
  app::MemorySink sink;
  ASSERT_EQ(runInProcess(c, sink).exit_code, app::kSuccess);
  int checked = 0;
  for (const app::ResultFrame& f : sink.frames()) {
    if (f.step_name != "shake") continue;
    const double t = f.state->time;
    const double second = 40 * 0.005;  // where the second schedule starts, as the run has it
    const double expected = t <= second ? std::round(t / 0.005) * 0.005
                                        : second + std::round((t - second) / 0.01) * 0.01;
    EXPECT_EQ(t, expected);
    ++checked;
  }
  EXPECT_EQ(checked, 16);  // the step's first state, 10 of the first schedule, 5 of the second
}

TEST(Simulation, RecordsCompletedOnTheWritingThreadAreTheRunThreadsOnes) {
  expectSameRecordsOnTheWritingThread(app::readCase(app::resolveCasePath("ex8-relaxation-test")),
                                      601);
  expectSameRecordsOnTheWritingThread(app::readCase(app::resolveCasePath("ex9-submerged-tube")),
                                      10);
  std::ifstream in(app::resolveCasePath("driven-taut-cable"));
  const std::string demo{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string damped = std::regex_replace(demo, std::regex("density: 7850 kg/m\\^3\\}"),
                                                "density: 7850 kg/m^3, damping: {zeta: 0.8}}");
  ASSERT_NE(damped, demo);
  const app::Case c = app::readCase(writeCase("damped-demo.yaml", damped));
  ASSERT_TRUE(c.model->element(0).hasDamping());
  expectSameRecordsOnTheWritingThread(c, 10);
}

}  // namespace
}  // namespace flexmoor::test
