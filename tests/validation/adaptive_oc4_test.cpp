// OC4 surge (cases/ocean/oc4-semi-surge.yaml, its first 200 s, everything else the case's)
// against the same run at a fixed step of 0.025 s, the converged reference: the six fairlead
// tension extremes over t >= 100 s (10 periods of the surge), relative.
// - Steps chosen by their accuracy at the default step_tolerance (0.01): within 5e-4 (measured
//   4.3e-4), in no more Newton iterations than the shipped fixed step of 0.1 s (measured 3,705
//   against 4,266; that step's own difference from the reference: 4.2e-4).
// - At step_tolerance 0.05, the setting of the speed target (docs/performance.md, Adaptive time
//   steps): within 2e-3 (measured 1.53e-3), in at most 0.45 of the fixed step's iterations
//   (measured 1,814, 0.43).
// - A fixed step of 0.4 s, at which points of the lines land on the seabed within a step: at most
//   1,650 Newton iterations and 200 backtracks (measured 1,598 and 167; 2,111 and 715 when the
//   first solve took the contact's matrices at the step's start instead of at the predictor).
#include <gtest/gtest.h>

#include <string>

#include "tests/support/case_files.hpp"
#include "tests/support/in_process_run.hpp"

namespace flexmoor::test {
namespace {

std::string shippedCase() { return shippedCaseText("ocean/oc4-semi-surge"); }

// The text with `from` (which must be there) replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The count the run's log reports before `what` ("..., N Newton iterations, ...").
long logged(const std::string& log, const std::string& what) {
  const size_t end = log.find(" " + what);
  EXPECT_NE(end, std::string::npos) << what << " in " << log;
  if (end == std::string::npos) return 0;
  const size_t start = log.rfind(' ', end - 1) + 1;
  return std::stol(log.substr(start, end - start));
}

// The case's first 200 s at a fixed step of dt with `steps` steps.
InProcessRun fixedStep(const std::string& name, const std::string& dt, int steps) {
  return runCaseInProcess(name, replaced(shippedCase(), "dt: 0.1 s, steps: 6000",
                                         "dt: " + dt + ", steps: " + std::to_string(steps)));
}

// The case's first 200 s with its steps chosen by their accuracy; `keys` after `output:`.
InProcessRun adaptive(const std::string& name, const std::string& keys) {
  const std::string text =
      replaced(shippedCase(), "dt: 0.1 s, steps: 6000,", "duration: 200 s, output: 0.1 s," + keys);
  return runCaseInProcess(name, replaced(text, ", output_every: 1}", "}"));
}

class AdaptiveStepsOc4 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = new InProcessRun(fixedStep("oc4-reference", "0.025 s", 8000));
    shipped_ = new InProcessRun(fixedStep("oc4-shipped", "0.1 s", 2000));
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete shipped_;
  }

  // The largest relative difference of the six extremes from the reference's.
  static double worstDifference(const InProcessRun& run) {
    double worst = 0.0;
    for (const char* stat : {"min", "max"})
      for (int line = 1; line <= 3; ++line) {
        const std::string key = std::string("tension_") + stat + "_" + std::to_string(line);
        worst = std::max(worst, std::abs(run.value(key) / reference_->value(key) - 1.0));
      }
    return worst;
  }

  static void expectRan(const InProcessRun& run) {
    ASSERT_EQ(reference_->exit_code, app::kSuccess) << reference_->log;
    ASSERT_EQ(shipped_->exit_code, app::kSuccess) << shipped_->log;
    ASSERT_EQ(run.exit_code, app::kSuccess) << run.log;
  }

  // The adaptive run with `keys` within `tolerance` of the reference, in at most `cost` times
  // the shipped step's Newton iterations.
  static void expectAdaptive(const std::string& name, const std::string& keys, double tolerance,
                             double cost) {
    const InProcessRun run = adaptive(name, keys);
    expectRan(run);
    const double worst = worstDifference(run);
    RecordProperty("worst_relative_difference", std::to_string(worst));
    EXPECT_LE(worst, tolerance);
    EXPECT_LE(logged(run.log, "Newton iterations"),
              cost * logged(shipped_->log, "Newton iterations"));
  }

  static InProcessRun* reference_;
  static InProcessRun* shipped_;
};

InProcessRun* AdaptiveStepsOc4::reference_ = nullptr;
InProcessRun* AdaptiveStepsOc4::shipped_ = nullptr;

TEST_F(AdaptiveStepsOc4, DefaultToleranceReachesTheConvergedExtremesAtNoMoreIterations) {
  expectAdaptive("oc4-adaptive", "", 5e-4, 1.0);
}

TEST_F(AdaptiveStepsOc4, LooserToleranceStaysWithinTheRequirementAtLessThanHalfTheCost) {
  expectAdaptive("oc4-adaptive-0.05", " step_tolerance: 0.05,", 2e-3, 0.45);
}

TEST_F(AdaptiveStepsOc4, LinesLandingOnTheSeabedWithinAStepCostFewBacktracks) {
  const InProcessRun run = fixedStep("oc4-fixed-0.4", "0.4 s", 500);
  expectRan(run);
  EXPECT_LE(logged(run.log, "Newton iterations"), 1650);
  EXPECT_LE(logged(run.log, "backtracks"), 200);
}

}  // namespace
}  // namespace flexmoor::test
