// Summary quantities taken over a dynamic step's time (at: and stat:), through the command, on an
// undamped spring-mass in free vibration: 1 kg on k = 4 pi^2 N/m (w = 2 pi rad/s, a period of
// 1 s), pulled to A = 1 cm by a static step and released at t = 0 (dynamic load factor 0), so
// x(t) = A cos(w t). Newmark's average acceleration with dt = T / 40 over four periods.
//
// Two references. The continuous closed form, to the time discretisation error: the scheme keeps
// the amplitude and lengthens the period, its discrete solution being exactly
//   x_n = A cos(n theta), u'_n = -A w sin(n theta), theta = 2 atan(w dt / 2),
// a phase lag of eps = 1 - theta / (w dt) = 2.05e-3 per radian ((w dt)^2 / 12 to leading order).
// And that discrete solution itself, to round-off: its values at the steps, their chords, and the
// trapezoidal sums in closed form (sum' cos(n theta) = sin(N theta) cot(theta / 2) / 2).
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::runText;
using flexmoor::test::scratch;
using flexmoor::test::summaryValue;

const double kA = 0.01, kW = 2.0 * M_PI, kK = kW * kW, kDt = 0.025;
const int kSteps = 160;
const double kTheta = 2.0 * std::atan(kW * kDt / 2.0);

std::string springMass(int output_every) {
  return R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [1 m, 0, 0]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 39.47841760435743 N/m, compression: carry}
  - {type: point_mass, node: 2, mass: 1 kg}
supports:
  - {node: 1, fix: [x, y, z]}
  - {node: 2, fix: [y, z]}
loads:
  nodal: [{node: 2, force: [0.3947841760435743 N, 0, 0]}]
steps:
  - static: {name: pulled}
  - dynamic: {name: released, load_factor: 0, dt: 0.025 s, steps: 160, output_every: )" +
         std::to_string(output_every) + R"(}
summary:
  x_end: {quantity: displacement_x, node: 2}
  x_at_end: {quantity: displacement_x, node: 2, at: 4 s}
  x_between: {quantity: displacement_x, node: 2, at: 1010 ms}
  x_max: {quantity: displacement_x, node: 2, stat: max}
  x_min: {quantity: displacement_x, node: 2, stat: min}
  x_mean: {quantity: displacement_x, node: 2, stat: mean}
  x_std: {quantity: displacement_x, node: 2, stat: std, window: {from: 0 s, to: 4 s}}
  speed_max: {quantity: speed, node: 2, stat: max}
  velocity_std: {quantity: velocity_x, node: 2, stat: std}
  tension_end: {quantity: end_tension, element: 1, end: first}
  tension_at_end: {quantity: end_tension, element: 1, end: first, at: 4 s}
  tension_max: {quantity: end_tension, element: 1, end: first, stat: max}
  max_tension_max: {quantity: max_tension, stat: max}
  reaction_min: {quantity: reaction_x, node: 1, stat: min}
)";
}

// displacement_x of node 2 (model node 1) in record `record` of DIR/sm.nc.
double recordedX(const std::filesystem::path& dir, size_t record) {
  int file = -1, var = -1;
  double x = std::nan("");
  EXPECT_EQ(nc_open((dir / "sm.nc").c_str(), NC_NOWRITE, &file), NC_NOERR);
  EXPECT_EQ(nc_inq_varid(file, "displacement_x", &var), NC_NOERR);
  const size_t start[2] = {record, 1}, count[2] = {1, 1};
  EXPECT_EQ(nc_get_vara_double(file, var, start, count, &x), NC_NOERR);
  nc_close(file);
  return x;
}

std::string run(const std::string& name, int output_every) {
  const auto dir = scratch(name);
  const auto r = runText(dir, "sm", springMass(output_every));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return flexmoor::test::readFile(dir / "sm.summary.json");
}

// at: 1.01 s lies between steps 40 (t = 1 s) and 41 (1.025 s), written as records 40 and 41
// (record 0 is the dynamic step's first state, t = 0). Its value is their chord to round-off (tolerance 1e-17 m,
// 1e-15 A); it is also the chord of the discrete solution A cos(n theta) (measured 4e-17 m,
// tolerance 1e-16 m), and it differs from A cos(w t) by the chord's sag near the crest,
// -f (1 - f) (w dt)^2 / 2 A = -2.96e-3 A at f = 0.4, less the phase lag's +0.8e-3 A: -2.2e-3 A
// predicted and measured, tolerance 2.5e-3 A.
TEST(SummaryOverTime, ValueBetweenStepsIsTheChordOfTheNeighbouringSteps) {
  const auto dir = scratch("summary-over-time-chord");
  const auto r = runText(dir, "sm", springMass(1));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string json = flexmoor::test::readFile(dir / "sm.summary.json");
  const double x = summaryValue(json, "x_between");
  const double x40 = recordedX(dir, 40), x41 = recordedX(dir, 41), f = (1.01 - 1.0) / kDt;
  EXPECT_NEAR(x, x40 + f * (x41 - x40), 1e-17);
  const double d40 = kA * std::cos(40 * kTheta), d41 = kA * std::cos(41 * kTheta);
  EXPECT_NEAR(x, d40 + f * (d41 - d40), 1e-16);
  EXPECT_NEAR(x, kA * std::cos(kW * 1.01), 2.5e-3 * kA);
  // At the step's end the value over time is the step-end value, to the bit: the same state,
  // one element's result against the frame's every element.
  EXPECT_EQ(summaryValue(json, "x_at_end"), summaryValue(json, "x_end"));
  EXPECT_EQ(summaryValue(json, "tension_at_end"), summaryValue(json, "tension_end"));
}

// Over the four periods [0, 4 s] (the default window, and the same given as from/to).
// Against x = A cos(w t): max A (the first state, t = 0, counts); min -A and speed max A w to
// the sampling, A (1 - cos(theta / 2)) = 3.1e-3 A at most (measured 2.1e-5 and 5.2e-6); mean 0
// and std A / sqrt(2) to the period lengthening: the discrete cosine runs 4 (1 - eps) periods,
// so mean -eps A and std (1 - eps / 2) A / sqrt(2) to first order (measured -0.9996 eps A and
// -0.498 eps; tolerances 1.02 eps A and 0.52 eps); the velocity's std A w / sqrt(2) likewise
// (measured +0.496 eps, tolerance 0.52 eps). The spring's end tension, and the largest over the
// elements, max k A, and the support reaction min -k A (the spring pulls node 1 in +x): the
// pulled state at t = 0, measured 9e-16 relative, tolerance 1e-14.
// Against the discrete solution, to round-off (measured 8e-14 and below, tolerance 1e-12
// relative): mean A sin(N theta) cot(theta / 2) / (2 N), mean square A^2 (1/2 + sin(2 N theta)
// cot(theta) / (4 N)), N = 160, and the least of A cos(n theta) and greatest of A w |sin(n theta)|.
TEST(SummaryOverTime, StatisticsOfAFreeVibrationOverWholePeriods) {
  const std::string json = run("summary-over-time-stats", 1);
  const double eps = 1.0 - kTheta / (kW * kDt), s2 = std::sqrt(2.0);
  EXPECT_NEAR(summaryValue(json, "x_max"), kA, 1e-14 * kA);
  EXPECT_NEAR(summaryValue(json, "x_min"), -kA, (1.0 - std::cos(kTheta / 2)) * kA);
  EXPECT_NEAR(summaryValue(json, "x_mean"), 0.0, 1.02 * eps * kA);
  EXPECT_NEAR(summaryValue(json, "x_std") / (kA / s2), 1.0, 0.52 * eps);
  EXPECT_NEAR(summaryValue(json, "speed_max") / (kA * kW), 1.0, 1.0 - std::cos(kTheta / 2));
  EXPECT_NEAR(summaryValue(json, "velocity_std") / (kA * kW / s2), 1.0, 0.52 * eps);
  EXPECT_NEAR(summaryValue(json, "tension_max") / (kK * kA), 1.0, 1e-14);
  EXPECT_NEAR(summaryValue(json, "max_tension_max") / (kK * kA), 1.0, 1e-14);
  EXPECT_NEAR(summaryValue(json, "reaction_min") / (-kK * kA), 1.0, 1e-14);

  const double N = kSteps;
  const double mean = kA * std::sin(N * kTheta) / std::tan(kTheta / 2) / (2 * N);
  const double square = kA * kA * (0.5 + std::sin(2 * N * kTheta) / std::tan(kTheta) / (4 * N));
  EXPECT_NEAR(summaryValue(json, "x_mean") / mean, 1.0, 1e-12);
  EXPECT_NEAR(summaryValue(json, "x_std") / std::sqrt(square - mean * mean), 1.0, 1e-12);
  double trough = 0.0, crest = 0.0;  // the discrete solution's extremes over the steps
  for (int n = 0; n <= kSteps; ++n) {
    trough = std::min(trough, kA * std::cos(n * kTheta));
    crest = std::max(crest, kA * kW * std::abs(std::sin(n * kTheta)));
  }
  EXPECT_NEAR(summaryValue(json, "x_min") / trough, 1.0, 1e-12);
  EXPECT_NEAR(summaryValue(json, "speed_max") / crest, 1.0, 1e-12);
}

// Every accepted step counts, not only those written: writing every 7th step (160 is no multiple
// of 7, so the last record is a forced one) leaves every value as it was, to the bit.
TEST(SummaryOverTime, OutputEveryDoesNotChangeTheValues) {
  const std::string all = run("summary-over-time-every-1", 1);
  const std::string some = run("summary-over-time-every-7", 7);
  for (const char* key : {"x_between", "x_max", "x_min", "x_mean", "x_std", "speed_max",
                          "velocity_std", "tension_max", "reaction_min"}) {
    ASSERT_TRUE(std::isfinite(summaryValue(all, key))) << key << "\n" << all;
    EXPECT_EQ(summaryValue(some, key), summaryValue(all, key)) << key;
  }
}

}  // namespace
