// A case run in process (apps/run/simulation.hpp) with an in-memory sink: the records are the
// ones the command streams to netCDF (one closing the relaxation, then one per accepted time step
// of Example 8), the summary is the command's, and the same Case runs again to the same numbers
// (a step's release of the buoy is undone when a run ends). Reference: the command's own run of
// the case (flexmoor run); tolerance 0, the same code on the same input.
#include "apps/run/simulation.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "apps/case/case_reader.hpp"
#include "apps/output/memory_sink.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

app::SimulationResult runInProcess(const app::Case& c, app::MemorySink& sink) {
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  simulation.addSink(sink);
  return simulation.run();
}

TEST(Simulation, RunsACaseInProcessAsTheCommandDoes) {
  const app::Case c = app::readCase(app::resolveCasePath("ex8-relaxation-test"));
  app::MemorySink first, second;
  const app::SimulationResult a = runInProcess(c, first);
  ASSERT_EQ(a.exit_code, app::kSuccess);
  ASSERT_EQ(first.frames().size(), 601u);
  EXPECT_EQ(first.frames().front().step_name, "held");
  EXPECT_NEAR(first.frames().back().state->time, 3.0, 1e-12);
  const std::string json = runNamedCase("ex8-relaxation-test");
  for (const auto& [name, value] : a.summary) EXPECT_EQ(value, summaryValue(json, name)) << name;

  const app::SimulationResult b = runInProcess(c, second);
  ASSERT_EQ(b.summary.size(), a.summary.size());
  for (size_t k = 0; k < a.summary.size(); ++k)
    EXPECT_EQ(b.summary[k].second, a.summary[k].second) << a.summary[k].first;
}

}  // namespace
}  // namespace flexmoor::test
