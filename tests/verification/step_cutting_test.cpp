// Automatic step cutting: a stiff spring pendulum (a point mass on a spring, released from the
// horizontal under gravity) swings through large rotations; with few Newton iterations allowed,
// coarse steps fail and are halved and retried, and the next step of the schedule is tried at
// its own size again. The result must match a fine run without cuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "libstruct/element/spring_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/newmark.hpp"

namespace flexmoor {
namespace {

// Pivot at the origin, a 1 kg mass at (1, 0, 0) on a spring of 1e4 N/m (rest length 1 m), moving
// in the x-z plane under g = 9.81 m/s^2. The pendulum period is about 2 s.
std::unique_ptr<model::Model> springPendulum() {
  auto m = std::make_unique<model::Model>();
  const int pivot = m->addNode(Eigen::Vector3d::Zero());
  const int bob = m->addNode(Eigen::Vector3d(1, 0, 0));
  m->addElement(std::make_unique<element::SpringElement>(pivot, bob, 1.0e4, -1.0,
                                                         material::Compression::Carry));
  m->addElement(std::make_unique<element::PointMassElement>(bob, 1.0));
  for (int k = 0; k < 3; ++k) m->constrain(pivot, k);
  m->constrain(bob, 1);
  m->setGravity(Eigen::Vector3d(0, 0, -9.81));
  m->numberEquations();
  return m;
}

struct Swing {
  solve::DynamicReport report;
  Eigen::Vector3d bob;
  std::vector<double> times;
  std::vector<std::string> messages;
};

Swing swing(double dt, int steps, int max_iterations) {
  const auto m = springPendulum();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  state.load_factor = 1.0;
  solve::DynamicOptions o;
  o.schedule = {{dt, steps}};
  o.max_iterations = max_iterations;
  o.max_step_cuts = 6;
  o.convergence.displacement_tolerance = 1e-10;
  Swing s;
  solve::SolveLog log;
  log.message = [&s](const std::string& text) { s.messages.push_back(text); };
  s.report = solve::integrate(assembler, state, o, log,
                              [&s](const model::State& st) { s.times.push_back(st.time); });
  s.bob = state.displacement.col(1);
  return s;
}

TEST(StepCutting, FailedStepsAreHalvedAndTheScheduleResumes) {
  const Swing coarse = swing(0.05, 20, 4);  // one second: down through the bottom and up again
  ASSERT_GT(coarse.report.cuts, 0);
  EXPECT_EQ(coarse.report.steps, 20 + coarse.report.cuts);  // each cut adds one step
  ASSERT_FALSE(coarse.messages.empty());
  EXPECT_NE(coarse.messages[0].find("halving"), std::string::npos) << coarse.messages[0];
  EXPECT_NEAR(coarse.times.back(), 1.0, 1e-12);
  // A cut step's halves end where the step would have: every time of the schedule, k 0.05 s,
  // is among the accepted steps' times. And the schedule resumes: each of its steps is tried at
  // its own length first, so every schedule step that was cut logged a failure at dt = 0.05 s.
  int cut_schedule_steps = 0;
  for (int k = 1; k <= 20; ++k) {
    const auto end = std::find_if(coarse.times.begin(), coarse.times.end(),
                                  [k](double t) { return std::abs(t - 0.05 * k) < 1e-12; });
    ASSERT_NE(end, coarse.times.end()) << "no step ends at " << 0.05 * k << " s";
    const double start = end == coarse.times.begin() ? 0.0 : *(end - 1);
    if (std::abs(0.05 * k - start - 0.05) > 1e-12) ++cut_schedule_steps;
  }
  const auto full_length_failures =
      std::count_if(coarse.messages.begin(), coarse.messages.end(), [](const std::string& m) {
        return m.find("with dt = 0.05 s, halving") != std::string::npos;
      });
  EXPECT_GT(cut_schedule_steps, 0);
  EXPECT_EQ(full_length_failures, cut_schedule_steps);

  // The same second with a step 16 times smaller and Newton converging without cuts.
  const Swing fine = swing(0.05 / 16, 320, 30);
  EXPECT_EQ(fine.report.cuts, 0);
  RecordProperty("cuts", coarse.report.cuts);
  RecordProperty("difference_m", std::to_string((coarse.bob - fine.bob).norm()));
  EXPECT_LT((coarse.bob - fine.bob).norm(), 0.02)
      << coarse.bob.transpose() << " vs " << fine.bob.transpose();
}

TEST(StepCutting, GivesUpWithWhereAndWhyWhenCutsRunOut) {
  const auto m = springPendulum();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  state.load_factor = 1.0;
  solve::DynamicOptions o;
  o.schedule = {{0.05, 20}};
  o.max_iterations = 1;  // one iteration never meets 1e-10 on a rotating spring
  o.convergence.displacement_tolerance = 1e-10;
  o.max_step_cuts = 2;
  try {
    solve::integrate(assembler, state, o);
    FAIL() << "expected a ConvergenceError";
  } catch (const solve::ConvergenceError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge even with dt = 0.0125 s"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexmoor
