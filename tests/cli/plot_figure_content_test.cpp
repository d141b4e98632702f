// What the run figures of `flexmoor plot` draw (apps/plot/flexmoor_plot.py), read back from the
// figure itself: the plot's drawing functions run in Python on a run's netCDF, and the data of
// the lines they put on the axes printed and compared here with the netCDF read by the netCDF C
// API and with libhydro. The run is the taut wire in a JONSWAP sea (tests/support/wire_in_a_sea),
// 200 records of 0.25 s. And the one path of a spectrum that a solver's step cuts would take,
// records not evenly spaced, on records made up for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "libhydro/signal/welch.hpp"
#include "libhydro/waves/wave_spectrum.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/netcdf_reader.hpp"
#include "tests/support/wire_in_a_sea.hpp"

namespace flexmoor::test {
namespace {

// Runs `body` in Python after importing the plot (as p), numpy (as np), xarray (as xr) and
// argparse.
CliRun python(const std::string& body) {
  const CliRun r =
      command("/usr/bin/python3 -c \"import sys, argparse; sys.path.insert(0, '" FLEXMOOR_SOURCE_DIR
              "/apps/plot'); import numpy as np, xarray as xr, flexmoor_plot as p; " +
              body + "\"");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r;
}

// The lines' data of the figure `draw` returns, x then y of each line on its first axes.
std::string printLines(const std::string& draw) {
  return "f, _ = " + draw +
         "; [print(*l.get_xdata()) or print(*l.get_ydata()) for l in f.axes[0].lines]";
}

// `--spectrum wave_elevation --segment 50`: the estimate drawn is libhydro's Welch estimate
// (signal::welch, 200-sample segments) of the file's wave_elevation over the dynamic step's 201
// records, at every one of its 101 frequencies, to 1.5e-15 of its peak (measured 6.9e-16: numpy's
// FFT against FFTW; relative to each bin up to 5e-10 above the sea's band, where the density is
// round-off, 1e-12 of the peak); the target drawn is the file's sea, JONSWAP Hs 2 m, Tp 8 s,
// gamma 3.3 (WaveSpectrum::density), at each of its 2,000 points where it exceeds 1e-12 of its
// peak, to 2e-14 relative (measured 9.8e-15: the same Simpson sums in another order).
TEST(PlotFigureContent, SpectrumDrawsTheWelchEstimateOfTheSeriesAndTheFilesTarget) {
  const auto nc = runWireInASea("figure-content-spectrum", 200);
  const auto lines =
      printedNumbers(python(printLines("p.draw_spectrum(xr.open_dataset('" + nc.string() +
                                       "'), argparse.Namespace(spectrum='wave_elevation', "
                                       "segment=50.0, start=None))")));
  ASSERT_EQ(lines.size(), 4u);  // the estimate, the target
  const std::vector<double> eta = NetcdfReader(nc.string()).doubles("wave_elevation");
  ASSERT_EQ(eta.size(), 201u);
  const signal::SpectralEstimate e = signal::welch(eta, 0.25, 200);
  ASSERT_EQ(lines[0].size(), e.omega.size());
  ASSERT_EQ(lines[1].size(), e.density.size());
  const double peak = *std::max_element(e.density.begin(), e.density.end());
  double worst = 0.0;
  for (size_t k = 1; k < e.omega.size(); ++k) {
    EXPECT_NEAR(lines[0][k] / e.omega[k], 1.0, 1e-14) << k;
    worst = std::max(worst, std::abs(lines[1][k] - e.density[k]) / peak);
  }
  EXPECT_LT(worst, 1.5e-15);
  const hydro::WaveSpectrum target = hydro::WaveSpectrum::jonswap(2.0, 8.0, 3.3);
  ASSERT_EQ(lines[2].size(), 2000u);
  ASSERT_EQ(lines[3].size(), 2000u);
  double worst_target = 0.0;
  for (size_t k = 0; k < lines[2].size(); ++k) {
    const double s = target.density(lines[2][k]);
    if (s > 1e-12 * target.density(target.peakFrequency()))
      worst_target = std::max(worst_target, std::abs(lines[3][k] / s - 1.0));
  }
  EXPECT_LT(worst_target, 2e-14);
}

// `--shapes 0,10,20,50`: one line of markers per time, at the nodes' positions (x, z) of the
// records at 0, 10, 20 and 50 s (the dynamic step's: records 0, 40, 80, 200), as the file holds
// them: equal.
TEST(PlotFigureContent, ShapesDrawTheNodesWhereTheRecordsPutThem) {
  const auto nc = runWireInASea("figure-content-shapes", 200);
  const auto lines =
      printedNumbers(python(printLines("p.draw_shapes(xr.open_dataset('" + nc.string() +
                                       "'), argparse.Namespace(shapes='0,10,20,50', "
                                       "plane='xz'))")));
  ASSERT_EQ(lines.size(), 8u);
  const NetcdfReader file(nc.string());
  const std::vector<double> x = file.doubles("position_x"), z = file.doubles("position_z");
  const size_t nodes = file.dimension("node");
  ASSERT_EQ(nodes, 5u);
  const int records[] = {0, 40, 80, 200};
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(lines[2 * i].size(), nodes);
    for (size_t n = 0; n < nodes; ++n) {
      EXPECT_EQ(lines[2 * i][n], x[records[i] * nodes + n]) << "shape " << i << ", node " << n;
      EXPECT_EQ(lines[2 * i + 1][n], z[records[i] * nodes + n]) << "shape " << i << ", node " << n;
    }
  }
  // The wire sags between its ends and moves with the sea: the shapes differ.
  EXPECT_NE(lines[3][2], lines[5][2]);
}

// Records of a step whose time steps were cut (0.25 s, some halved: 11 records over 2 s) are
// interpolated linearly onto the step's largest time step before Welch: a series linear in time
// comes back exactly on the grid 0, 0.25, ..., 2 s (1e-15), with the message saying so.
TEST(PlotFigureContent, UnevenRecordsAreInterpolatedOntoTheLargestTimeStep) {
  const std::string body =
      "t = np.array([0, 0.25, 0.5, 0.625, 0.75, 1.0, 1.25, 1.375, 1.5, 1.75, 2.0]); "
      "ds = xr.Dataset({'step_number': ('time', np.full(t.size, 2))}, coords={'time': t}); "
      "x, dt = p.last_dynamic_record(ds, 3.0 + 2.0 * t, None); print(dt); print(*x)";
  const CliRun r = python(body);
  const auto lines = printedNumbers(r);
  ASSERT_EQ(lines.size(), 2u);
  ASSERT_EQ(lines[0].size(), 1u);
  EXPECT_EQ(lines[0][0], 0.25);
  ASSERT_EQ(lines[1].size(), 9u);
  for (int j = 0; j < 9; ++j) EXPECT_NEAR(lines[1][j], 3.0 + 2.0 * 0.25 * j, 1e-15) << j;
  EXPECT_NE(r.errors.find("not evenly spaced (dt 0.125 to 0.25): interpolated onto dt = 0.25"),
            std::string::npos)
      << r.errors;
}

}  // namespace
}  // namespace flexmoor::test
