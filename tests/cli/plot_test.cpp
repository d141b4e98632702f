// Figures a person reads: `flexmoor plot` (apps/plot/flexmoor_plot.py with Debian's matplotlib
// under the system interpreter) draws time series of a run's netCDF as a PNG, and refuses a
// series it cannot find.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;

flexmoor::test::CliRun plot(const std::string& args) { return flexmoor("plot " + args); }
using flexmoor::test::pngSize;

TEST(Plot, DrawsChosenSeriesOfARunAsAPng) {
  const auto dir = flexmoor::test::scratch("plot");
  ASSERT_EQ(flexmoor("run driven-taut-cable -o " + dir.string()).exit_code, 0);
  const std::string nc = (dir / "driven-taut-cable.nc").string();
  const std::string png = (dir / "series.png").string();
  const auto c = plot(nc + " -o " + png +
                      " --series displacement_z@node=5 --series speed@node=5"
                      " --series tension_end@element=4,end=2");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("3 panels"), std::string::npos) << c.output;
  const auto [width, height] = pngSize(png);
  EXPECT_GT(width, 800u);   // 8 in at 130 dpi
  EXPECT_GT(height, 900u);  // three panels
  const auto defaults = plot(nc + " -o " + (dir / "default.png").string());
  ASSERT_EQ(defaults.exit_code, 0) << defaults.output;
  EXPECT_GT(pngSize((dir / "default.png").string()).first, 0u);
}

TEST(Plot, RefusesASeriesTheFileDoesNotHold) {
  const auto dir = flexmoor::test::scratch("plot-bad");
  ASSERT_EQ(flexmoor("run driven-taut-cable -o " + dir.string()).exit_code, 0);
  const std::string nc = (dir / "driven-taut-cable.nc").string();
  const auto missing = plot(nc + " -o " + (dir / "x.png").string() + " --series buoy_x@node=1");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("no variable 'buoy_x'"), std::string::npos) << missing.output;
  const auto unindexed = plot(nc + " -o " + (dir / "y.png").string() + " --series position_x");
  EXPECT_NE(unindexed.exit_code, 0);
  EXPECT_NE(unindexed.output.find("needs an index for node"), std::string::npos)
      << unindexed.output;
}

// An element's end reads the same in the plot as in the case files: end=1 and end=first the
// first node's (the file's end coordinate, sel(end=1)), end=2 and end=last the last's; the values
// are the file's own (compared exactly with xarray's isel on the end dimension).
TEST(Plot, SeriesEndsAreFirstLastOneOrTwo) {
  const auto dir = flexmoor::test::scratch("plot-ends");
  ASSERT_EQ(flexmoor("run driven-taut-cable -o " + dir.string() + " --no-figure").exit_code, 0);
  const std::string script =
      "import sys; sys.path.insert(0, '" FLEXMOOR_SOURCE_DIR
      "/apps/plot'); import numpy as np, xarray as xr, flexmoor_plot as p; "
      "ds = xr.open_dataset(sys.argv[1]); "
      "s = lambda spec: p.select(ds, *p.parse_spec(spec))[0].values; "
      "t = ds.tension_end.sel(element=4); "
      "print(np.array_equal(s('tension_end@element=4,end=1'), t.isel(end=0).values), "
      "np.array_equal(s('tension_end@element=4,end=first'), t.isel(end=0).values), "
      "np.array_equal(s('tension_end@element=4,end=2'), t.isel(end=1).values), "
      "np.array_equal(s('tension_end@element=4,end=last'), t.isel(end=1).values), "
      "np.array_equal(t.isel(end=0).values, t.isel(end=1).values))";
  const auto r = flexmoor::test::command("/usr/bin/python3 -c \"" + script + "\" " +
                                         (dir / "driven-taut-cable.nc").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output, "True True True True False\n");  // the two ends differ: a real choice
  const auto bad = plot((dir / "driven-taut-cable.nc").string() + " -o " +
                        (dir / "x.png").string() + " --series tension_end@element=4,end=middle");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("or end=first or end=last"), std::string::npos) << bad.output;
}

}  // namespace
