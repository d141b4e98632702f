// A time-domain run through the command: a pretensioned cable driven at mid-span by a sine load,
// in two time-step segments (the schedule of the dissertation's Example 9), streamed to netCDF
// every fourth step, with a progress log.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;
using flexmoor::test::scratch;

// Steel cable, 10 m, stretched 1 mm: T = E A * 1e-3 = 2e4 N, mu = 0.785 kg/m, so the first mode
// is omega_1 = (pi / L) sqrt(T / mu) = 50 rad/s; the load's 0.5 s period is far below it.
const char* kPluckedCable = R"(name: driven-cable
units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4, density: 7850}
lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 8, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01, 0, 0]}
  - {nodes: cable, fix: [y]}
histories:
  wave: {type: sine, amplitude: 1, period: 0.5 s}
loads:
  nodal:
    - {node: cable.middle, force: [0, 0, 10 N], history: wave}
steps:
  - static: {name: pretension}
  - dynamic: {name: drive, schedule: [{dt: 0.005 s, steps: 40}, {dt: 0.01 s, steps: 20}],
              output_every: 4}
summary:
  deflection: {quantity: displacement_z, node: cable.middle}
)";

std::vector<double> readVariable(int file, const char* name, size_t count) {
  int var = -1;
  EXPECT_EQ(nc_inq_varid(file, name, &var), NC_NOERR) << name;
  std::vector<double> values(count);
  if (var >= 0) {
    EXPECT_EQ(nc_get_var_double(file, var, values.data()), NC_NOERR);
  }
  return values;
}

TEST(DynamicRun, StreamsEveryNthStepOfAScheduleAndReportsProgress) {
  const auto dir = scratch("dynamic");
  std::ofstream(dir / "driven.yaml") << kPluckedCable;
  const auto r = flexmoor("run " + (dir / "driven.yaml").string() + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("t = 0.4 s (100%), 60 steps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("60 time steps"), std::string::npos) << r.output;

  int file = -1;
  ASSERT_EQ(nc_open((dir / "driven-cable.nc").c_str(), NC_NOWRITE, &file), NC_NOERR);
  int step_dim = -1;
  size_t records = 0;
  ASSERT_EQ(nc_inq_dimid(file, "step", &step_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(file, step_dim, &records), NC_NOERR);
  // The static step's record, then accepted steps 4, 8, ..., 60 of the dynamic step.
  ASSERT_EQ(records, 1u + 15u);
  const std::vector<double> time = readVariable(file, "time", records);
  EXPECT_DOUBLE_EQ(time[0], 0.0);
  for (size_t k = 1; k <= 10; ++k) EXPECT_NEAR(time[k], 0.02 * k, 1e-12) << k;  // dt 0.005
  for (size_t k = 11; k < records; ++k)
    EXPECT_NEAR(time[k], 0.2 + 0.04 * (k - 10), 1e-12) << k;  // dt 0.01
  nc_close(file);

  // Bounded by the static deflection F L / (4 T) = 1.25 mm times the largest dynamic
  // amplification of an undamped start below resonance, (1 + r) / (1 - r^2) with r = 0.25.
  const std::string json = flexmoor::test::readFile(dir / "summary.json");
  const double w = flexmoor::test::summaryValue(json, "deflection");
  ASSERT_TRUE(std::isfinite(w)) << json;
  EXPECT_GT(std::abs(w), 0.0);
  EXPECT_LT(std::abs(w), 1.25e-3 * 1.25 / (1.0 - 0.0625) * 1.05);
}

}  // namespace
