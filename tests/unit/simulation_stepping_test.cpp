// The life cycle a host drives (apps/run/simulation.hpp): prepare, advanceTo, save, restore,
// finish. Example 8 (a buoy released on its rope after a relaxation) stepped by a caller gives
// the records and summary of its run() (reference: run(); tolerance 0); a checkpoint holds its
// records back until it is gone, and a restore takes back those after it, so the sink sees each
// time once, in order, with the values of a run that never went back.
#include <gtest/gtest.h>

#include <sstream>

#include "apps/case/case_reader.hpp"
#include "apps/output/memory_sink.hpp"
#include "apps/run/simulation.hpp"

namespace flexmoor::test {
namespace {

struct Run {
  app::SimulationResult result;
  app::MemorySink sink;
};

void expectSameRecords(const app::MemorySink& a, const app::MemorySink& b) {
  ASSERT_EQ(a.frames().size(), b.frames().size());
  for (size_t k = 0; k < a.frames().size(); ++k) {
    const model::State& x = *a.frames()[k].state;
    const model::State& y = *b.frames()[k].state;
    ASSERT_EQ(x.time, y.time) << "record " << k;
    ASSERT_EQ(a.frames()[k].stage, b.frames()[k].stage) << "record " << k;
    ASSERT_EQ((x.displacement - y.displacement).cwiseAbs().maxCoeff(), 0.0) << "record " << k;
    ASSERT_EQ((x.velocity - y.velocity).cwiseAbs().maxCoeff(), 0.0) << "record " << k;
  }
}

// Check SS1. Stepped in host-sized steps of 0.05 s (ten of its 0.005 s steps each, the host's
// times on the case's grid: t0 + 10 n dt), then finished: every record as run() gives it.
TEST(SimulationStepping, AHostsStepsGiveTheRunsRecordsAndSummary) {
  const app::Case c = app::readCase(app::resolveCasePath("ex8-relaxation-test"));
  std::ostringstream log, diag;
  app::MemorySink whole, stepped;
  app::SimulationResult reference;
  {
    app::Simulation s(c, log, diag);
    s.addSink(whole);
    reference = s.run();
  }
  app::Simulation s(c, log, diag);
  s.addSink(stepped);
  s.prepare();
  ASSERT_TRUE(s.stepping());
  const double start = s.time();
  for (int n = 1; n <= 40; ++n) s.advanceTo(start + (10 * n) * 0.005);
  const app::SimulationResult result = s.finish();
  EXPECT_THROW(s.advanceTo(10.0), std::logic_error);
  // The case's dynamic step is longer than 2 s: the host ended it at 2 s, so compare the records
  // up to there and the summary values the host's run reached.
  ASSERT_GT(whole.frames().size(), stepped.frames().size());
  app::MemorySink prefix;
  for (const app::ResultFrame& f : whole.frames())
    if (f.state->time <= s.time() && !f.stage) prefix.write(f);
  app::MemorySink time_records;
  for (const app::ResultFrame& f : stepped.frames())
    if (!f.stage) time_records.write(f);
  expectSameRecords(prefix, time_records);
  EXPECT_EQ(result.exit_code, app::kSuccess);
}

// Check SS2. Save at 0.5 s, advance to 1 s, restore, advance to 1 s again, drop the checkpoint,
// finish: the sink's records are those of a run that went straight to 1 s (tolerance 0), each
// time once; while the checkpoint lived, no record after 0.5 s reached the sink.
TEST(SimulationStepping, ARestoreTakesBackTheRecordsAfterItsCheckpoint) {
  const app::Case c = app::readCase(app::resolveCasePath("ex8-relaxation-test"));
  std::ostringstream log, diag;
  double start = 0.0;  // the dynamic step's start; the host steps on its grid, start + k dt
  const auto stepTo = [&start](app::Simulation& s, int from, int to) {
    for (int k = from + 10; k <= to; k += 10) s.advanceTo(start + k * 0.005);
  };
  app::MemorySink straight, back;
  {
    app::Simulation s(c, log, diag);
    s.addSink(straight);
    s.prepare();
    start = s.time();
    stepTo(s, 0, 200);
    s.finish();
  }
  app::Simulation s(c, log, diag);
  s.addSink(back);
  s.prepare();
  stepTo(s, 0, 100);
  auto checkpoint = s.save();
  const size_t at_save = back.frames().size();
  stepTo(s, 100, 200);
  EXPECT_EQ(back.frames().size(), at_save);  // held back
  s.restore(*checkpoint);
  EXPECT_EQ(s.time(), start + 100 * 0.005);
  stepTo(s, 100, 200);
  checkpoint.reset();
  s.finish();
  expectSameRecords(straight, back);
}

}  // namespace
}  // namespace flexmoor::test
