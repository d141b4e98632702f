// A spread mooring's figure when its case gives none (`figure: {kind: mooring}`, drawn by
// apps/plot/mooring_figure.py): each anchored line's fairlead tension over time and its profile
// in its vertical plane over the seabed and under the water line. Read back from the figure: the
// plot's drawing function runs in Python on the run's netCDF and prints the data of the lines it
// put on the axes, compared here with the case's geometry and the netCDF's tensions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/support/case_files.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/netcdf_reader.hpp"

namespace flexmoor::test {
namespace {

std::string shipped(const std::string& name) { return shippedCaseText("ocean/" + name); }

// The lines of the mooring figure's axes `axes` (0: the tensions, 1: the profiles when the run
// has time records), x then y of each, as numbers.
std::vector<std::vector<double>> drawn(const std::string& nc, int axes) {
  const CliRun r =
      command("/usr/bin/python3 -c \"import sys, argparse; sys.path.insert(0, '" FLEXMOOR_SOURCE_DIR
              "/apps/plot'); import xarray as xr, mooring_figure as m; f, _ = m.draw_mooring("
              "xr.open_dataset('" +
              nc +
              "'), argparse.Namespace()); [print(*l.get_xdata()) or print(*l.get_ydata()) for l in "
              "f.axes[" +
              std::to_string(axes) + "].lines]\"");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return printedNumbers(r);
}

// OC4's statics: no figure: block, so the run draws the mooring figure; its one panel holds, per
// line, the profile (from the anchor at z = -200 m, distance 0, to the fairlead at z = -14 m,
// 796.73 m away: hypot(418.8 - 20.434, 725.383 - 35.393) for lines 1 and 3, 837.6 - 40.868 for
// line 2), then the seabed under it
// (z = -200 m), and the water line at z = 0. Exact to the netCDF's positions (1e-9 m).
TEST(MooringFigure, ASpreadMooringDrawsItsProfilesOverTheBedWithoutAFigureBlock) {
  const auto dir = scratch("mooring-figure-statics");
  const CliRun r = runText(dir, "oc4-statics", shipped("oc4-semi-statics"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(pngSize(dir / "oc4-statics.png").first, 0u) << r.output;
  const auto lines = drawn((dir / "oc4-statics.nc").string(), 0);
  ASSERT_EQ(lines.size(), 2u * (3 + 3 + 1));  // 3 profiles, 3 beds, the water line
  const double oblique = std::hypot(418.8 - 20.434, 725.383 - 35.393);
  const double spans[3] = {oblique, 837.6 - 40.868, oblique};
  for (int k = 0; k < 3; ++k) {
    const std::vector<double>&x = lines[2 * k], &z = lines[2 * k + 1];
    ASSERT_GT(x.size(), 10u);
    EXPECT_EQ(x.front(), 0.0);
    EXPECT_NEAR(x.back(), spans[k], 1e-9) << "line " << k + 1;
    EXPECT_NEAR(z.front(), -200.0, 1e-9);
    EXPECT_NEAR(z.back(), -14.0, 1e-9);
    for (const double bed : lines[6 + 2 * k + 1]) EXPECT_EQ(bed, -200.0);
  }
  for (const double level : lines[13]) EXPECT_EQ(level, 0.0);
}

// OC4's surge, 20 s (its summary, over t >= 100 s, left out): the upper panel's lines are the fairlead tensions of lines 1-3 in MN over
// the records, each equal to the netCDF's tension_end at its line's last element's last end
// (the lines run from anchor to fairlead) divided by 1e6, to round-off.
TEST(MooringFigure, TheTensionPanelIsEachLinesFairleadTension) {
  std::string text = shipped("oc4-semi-surge");
  text = text.substr(0, text.find("summary:"));
  const std::string steps = "steps: 6000";
  text.replace(text.find(steps), steps.size(), "steps: 200");
  const auto dir = scratch("mooring-figure-surge");
  const CliRun r = runText(dir, "oc4-surge", text);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string nc = (dir / "oc4-surge.nc").string();
  const auto lines = drawn(nc, 0);
  ASSERT_EQ(lines.size(), 6u);
  const std::vector<double> tension = NetcdfReader(nc).doubles("tension_end");  // time, el., end
  const size_t records = lines[0].size(), elements = tension.size() / (2 * records);
  ASSERT_EQ(records, 201u);
  ASSERT_EQ(elements, 36u);
  for (size_t k = 0; k < 3; ++k) {
    const size_t last = 12 * (k + 1) - 1;
    for (size_t t = 0; t < records; ++t)
      EXPECT_NEAR(lines[2 * k + 1][t], tension[(t * elements + last) * 2 + 1] / 1e6, 1e-12)
          << "line " << k + 1 << " record " << t;
  }
}

}  // namespace
}  // namespace flexmoor::test
