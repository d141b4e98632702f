#include "tests/support/twin_runs.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "apps/case/build/build_case.hpp"

namespace flexmoor::test {

void runRecorded(const app::Case& c, RecordedRun& out) {
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  simulation.addSink(out.records);
  out.result = simulation.run();
}

void expectRefused(const app::CaseSpec& spec, const std::string& part) {
  try {
    app::buildCase(spec);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "not refused: " << part;
}

void expectSameModel(const model::Model& a, const model::Model& b) {
  ASSERT_EQ(a.nodeCount(), b.nodeCount());
  ASSERT_EQ(a.elementCount(), b.elementCount());
  ASSERT_EQ(a.equationCount(), b.equationCount());
  EXPECT_EQ(a.reference(), b.reference());
  for (int e = 0; e < a.elementCount(); ++e) {
    EXPECT_EQ(a.element(e).typeName(), b.element(e).typeName()) << e;
    EXPECT_EQ(a.element(e).nodes(), b.element(e).nodes()) << e;
  }
  for (int n = 0; n < a.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.equation(n, k), b.equation(n, k)) << n << " " << k;
      EXPECT_EQ(a.prescribed(n, k), b.prescribed(n, k)) << n << " " << k;
    }
  EXPECT_EQ(a.gravity(), b.gravity());
  EXPECT_EQ(a.lineLoads().size(), b.lineLoads().size());
  EXPECT_EQ(a.nodeLoads().size(), b.nodeLoads().size());
  EXPECT_EQ(a.nodalLoads().size(), b.nodalLoads().size());
  EXPECT_EQ(a.startState().displacement, b.startState().displacement);
}

void expectSameRecords(const RecordedRun& a, const RecordedRun& b) {
  ASSERT_EQ(a.result.exit_code, app::kSuccess);
  ASSERT_EQ(b.result.exit_code, app::kSuccess);
  const std::vector<app::ResultFrame>&p = a.records.frames(), &q = b.records.frames();
  ASSERT_EQ(p.size(), q.size());
  for (size_t i = 0; i < p.size(); ++i) {
    const model::State &s = *p[i].state, &t = *q[i].state;
    ASSERT_EQ(s.time, t.time) << i;
    ASSERT_EQ(s.displacement, t.displacement) << "record " << i << " at t = " << s.time;
    ASSERT_EQ(s.velocity, t.velocity) << "record " << i;
    ASSERT_EQ(s.acceleration, t.acceleration) << "record " << i;
    ASSERT_EQ(p[i].reactions, q[i].reactions) << "record " << i;
  }
}

void expectSameSummary(const RecordedRun& a, const RecordedRun& b) {
  ASSERT_EQ(a.result.summary.size(), b.result.summary.size());
  for (size_t i = 0; i < a.result.summary.size(); ++i) {
    EXPECT_EQ(a.result.summary[i].first, b.result.summary[i].first);
    if (a.result.summary[i].first != "cpu_seconds") {
      EXPECT_EQ(a.result.summary[i].second, b.result.summary[i].second)
          << a.result.summary[i].first;
    }
  }
}

}  // namespace flexmoor::test
