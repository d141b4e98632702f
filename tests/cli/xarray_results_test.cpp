// Results as the Python ecosystem reads them: xarray (Debian's python3-xarray, with the system
// interpreter) opens a run's netCDF and must find its CF coordinates, select a time slice by
// `time`, and see fill values where a quantity does not apply (tests/cli/xarray_check.py).
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;

// Runs `case_name` and xarray_check.py on its result; the script prints one line per check.
void expectXarrayReads(const std::string& case_name, const std::string& flags) {
  const auto dir = flexmoor::test::scratch("xarray-" + case_name);
  const auto run = flexmoor("run " + case_name + " -o " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string command = "/usr/bin/python3 " + std::string(FLEXMOOR_SOURCE_DIR) +
                              "/tests/cli/xarray_check.py " + (dir / (case_name + ".nc")).string() +
                              " " + flags + " 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  EXPECT_EQ(pclose(pipe), 0) << output;
  EXPECT_NE(output.find("as intended"), std::string::npos) << output;
}

// A time history with modes: time coordinate, time slices, node coordinates, mode-shape units.
TEST(XarrayReadsResults, TimeHistoryFindsCoordinatesAndSelectsByTime) {
  expectXarrayReads("driven-taut-cable", "");
}

// Cables and membranes in one file: tension_end is missing (NaN) on membranes, finite on cables.
TEST(XarrayReadsResults, MixedModelMasksWhatDoesNotApply) {
  expectXarrayReads("ex5-cable-reinforced-tube", "--mixed");
}

// An axisymmetric meridian: its reactions are per radian of circumference, and say so.
TEST(XarrayReadsResults, AxisymmetricReactionsArePerRadian) {
  expectXarrayReads("ex3-tube-inflation-axisymmetric", "--per-radian");
}

}  // namespace
