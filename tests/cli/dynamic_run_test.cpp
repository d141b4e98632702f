// A time-domain run through the command: a pretensioned cable driven at mid-span by a sine load,
// in two time-step segments (the schedule of the dissertation's Example 9), streamed to netCDF
// every fourth step, with a progress log; its pretension and first mode against closed forms.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;
using flexmoor::test::scratch;

std::vector<double> readVariable(int file, const char* name, size_t count) {
  int var = -1;
  EXPECT_EQ(nc_inq_varid(file, name, &var), NC_NOERR) << name;
  std::vector<double> values(count);
  if (var >= 0) {
    EXPECT_EQ(nc_get_var_double(file, var, values.data()), NC_NOERR);
  }
  return values;
}

// The named case cases/demo/driven-taut-cable.yaml: pretension, modes, then 60 Newmark steps.
TEST(DynamicRun, StreamsEveryNthStepOfAScheduleAndReportsProgress) {
  const auto dir = scratch("dynamic");
  const auto r = flexmoor("run driven-taut-cable -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("t = 0.4 s (100%), 60 steps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("60 time steps"), std::string::npos) << r.output;

  int file = -1;
  ASSERT_EQ(nc_open((dir / "driven-taut-cable.nc").c_str(), NC_NOWRITE, &file), NC_NOERR);
  int step_dim = -1;
  size_t records = 0;
  ASSERT_EQ(nc_inq_dimid(file, "time", &step_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(file, step_dim, &records), NC_NOERR);
  // The dynamic step's first state, then its accepted steps 4, 8, ..., 60; the static and the
  // modes step's states are the stage records of steps 1 and 2, at time 0.
  ASSERT_EQ(records, 1u + 15u);
  const std::vector<double> time = readVariable(file, "time", records);
  EXPECT_DOUBLE_EQ(time[0], 0.0);
  for (size_t k = 1; k <= 10; ++k) EXPECT_NEAR(time[k], 0.02 * k, 1e-12) << k;  // dt 0.005
  for (size_t k = 11; k <= 15; ++k)
    EXPECT_NEAR(time[k], 0.2 + 0.04 * (k - 10), 1e-12) << k;  // dt 0.01
  int stage_dim = -1;
  size_t stages = 0;
  ASSERT_EQ(nc_inq_dimid(file, "stage", &stage_dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(file, stage_dim, &stages), NC_NOERR);
  ASSERT_EQ(stages, 2u);
  EXPECT_EQ(readVariable(file, "stage", stages), (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(readVariable(file, "stage_time", stages), (std::vector<double>{0.0, 0.0}));
  nc_close(file);

  // Pretension and first mode: E A (lambda^2 - 1) / 2 lambda with lambda = 1.001, and the
  // consistent-mass string of 8 linear elements, omega^2 = (6 S / (rho h0^2)) (1 - cos(pi / 8)) /
  // (2 + cos(pi / 8)) with S = E (lambda^2 - 1) / 2 (reference quantities, Eq. 2.53).
  const std::string json = flexmoor::test::readFile(dir / "driven-taut-cable.summary.json");
  const double lambda = 1.001, S = 2.0e11 * (lambda * lambda - 1.0) / 2.0, h0 = 10.0 / 8;
  const double c = std::cos(M_PI / 8);
  EXPECT_NEAR(flexmoor::test::summaryValue(json, "tension") / (S * 1.0e-4 * lambda), 1.0, 1e-9);
  EXPECT_NEAR(flexmoor::test::summaryValue(json, "omega_1") /
                  std::sqrt(6.0 * S / (7850.0 * h0 * h0) * (1.0 - c) / (2.0 + c)),
              1.0, 1e-8);
  // Bounded by the static deflection F L / (4 T) = 1.25 mm times the largest dynamic
  // amplification of an undamped start below resonance, (1 + r) / (1 - r^2) with r = 0.25.
  const double w = flexmoor::test::summaryValue(json, "deflection");
  ASSERT_TRUE(std::isfinite(w)) << json;
  EXPECT_GT(std::abs(w), 0.0);
  EXPECT_LT(std::abs(w), 1.25e-3 * 1.25 / (1.0 - 0.0625) * 1.05);
}

// `output: fields: [position, velocity]` on the same case: the records hold those two fields
// only, with the very values of the full file (bit for bit: the same states), and the summary,
// the VTK files and the figure-free run are what the full run gives (the summary is taken from
// the states, not from the file).
TEST(DynamicRun, TheOutputFieldsListedAreTheOnlyOnesWrittenAndTheSameNumbers) {
  const std::string text = flexmoor::test::readFile(std::filesystem::path(FLEXMOOR_SOURCE_DIR) /
                                                    "cases/demo/driven-taut-cable.yaml");
  const auto full_dir = scratch("fields-full"), lean_dir = scratch("fields-lean");
  ASSERT_EQ(flexmoor::test::runText(full_dir, "demo", text).exit_code, 0);
  const auto r =
      flexmoor::test::runText(lean_dir, "demo", text + "output:\n  fields: [position, velocity]\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(flexmoor::test::readFile(full_dir / "driven-taut-cable.summary.json"),
            flexmoor::test::readFile(lean_dir / "driven-taut-cable.summary.json"));
  EXPECT_EQ(flexmoor::test::readFile(full_dir / "driven-taut-cable-3.vtk"),
            flexmoor::test::readFile(lean_dir / "driven-taut-cable-3.vtk"));

  int full = -1, lean = -1;
  ASSERT_EQ(nc_open((full_dir / "driven-taut-cable.nc").c_str(), NC_NOWRITE, &full), NC_NOERR);
  ASSERT_EQ(nc_open((lean_dir / "driven-taut-cable.nc").c_str(), NC_NOWRITE, &lean), NC_NOERR);
  const size_t values = 16 * 9, stage_values = 2 * 9;  // records x nodes
  for (const char* name : {"position_x", "position_z", "velocity_z"}) {
    EXPECT_EQ(readVariable(full, name, values), readVariable(lean, name, values)) << name;
    const std::string stage = std::string("stage_") + name;
    EXPECT_EQ(readVariable(full, stage.c_str(), stage_values),
              readVariable(lean, stage.c_str(), stage_values))
        << stage;
  }
  int var = -1;
  for (const char* absent : {"displacement_x", "reaction_x", "tension_end", "tension_point",
                             "stage_displacement_x", "stage_tension_end"})
    EXPECT_EQ(nc_inq_varid(lean, absent, &var), NC_ENOTVAR) << absent;
  nc_close(full);
  nc_close(lean);
}

}  // namespace
