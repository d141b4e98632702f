// The axes of `flexmoor plot`'s figures (apps/plot/plot_common.py): forces in kN or MN chosen
// from their magnitude, plain tick labels with no offset or factor at an axis' end, and spectra
// whose frequency axis ends where their energy does. The figures are drawn by the plot's own
// functions from datasets made in Python and their axes read back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;

// Runs `body` (Python, indented by nothing) after importing the plot's modules as p (the run
// figures) and c (the helpers), numpy as np and xarray as xr; returns what it printed.
CliRun python(const std::string& name, const std::string& body) {
  const fs::path script = scratch(name) / "check.py";
  std::ofstream(script) << "import sys\nsys.path.insert(0, '" FLEXMOOR_SOURCE_DIR "/apps/plot')\n"
                        << "import numpy as np, xarray as xr\n"
                        << "import flexmoor_plot as p, plot_common as c, study_figures as s\n"
                        << "from types import SimpleNamespace\n"
                        << body;
  return command("/usr/bin/python3 " + script.string());
}

TEST(PlotAxes, ForcesAreShownInKilonewtonsOrMeganewtonsByTheirMagnitude) {
  const CliRun r = python("plot-axes-units", R"(
for values, units, largest in (([1.1e6, 1.7e6], "N", None), ([-8e5, 2e5], "N", None),
                               ([999.0], "N", None), ([4.5e11], "N2 s rad-1", 1.7e6),
                               ([2e3], "N/m", None), ([3e6], "m", None), ([3e6], "lbf", None)):
    shown, name = c.in_force_units(np.array(values), units, largest)
    print(name, *["%g" % v for v in shown])
)");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output,
            "MN 1.1 1.7\n"
            "kN -800 200\n"
            "N 999\n"
            "MN2 s rad-1 0.45\n"
            "kN/m 2\n"
            "m 3e+06\n"
            "lbf 3e+06\n");
}

TEST(PlotAxes, TickLabelsArePlainNumbers) {
  const CliRun r = python("plot-axes-ticks", R"(
for ticks in ([0, 0.2, 0.4, 0.6000000000000001], [1000000.5, 1000001, 1000001.5],
              [-1e-17, 2e-6, 4e-6], [0, 100, 200], [189.6, 189.8, 190.0], [2e7, 4e7]):
    print(*c.tick_labels(ticks))
)");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output,
            "0 0.2 0.4 0.6\n"
            "1000000.5 1000001 1000001.5\n"
            "0 2e-6 4e-6\n"
            "0 100 200\n"
            "189.6 189.8 190\n"
            "2e7 4e7\n");
}

// A run's records: 600 s at 0.1 s of an end tension 1.2 MN + 0.3 MN sin(0.6 t) and a node
// displacement 190 m + 0.4 m sin(0.6 t) (OC4's surge: the default figure showed "1e6" above
// its tension axis and 189.6 to 190.4 m as offsets).
const std::string kRun = R"(
t = np.arange(6001) * 0.1
wave = np.sin(0.6 * t)
tension = (1.2e6 + 3e5 * wave)[:, None, None] * np.ones((1, 2, 2))
moved = (190.0 + 0.4 * wave)[:, None] * np.array([[0.0, 1.0]])
ds = xr.Dataset(
    {"tension_end": (("time", "element", "end"), tension, {"units": "N"}),
     "displacement_x": (("time", "node"), moved, {"units": "m"}),
     "displacement_y": (("time", "node"), 0 * moved, {"units": "m"}),
     "displacement_z": (("time", "node"), 0 * moved, {"units": "m"}),
     "step_number": (("time",), np.full(t.size, 2))},
    coords={"time": ("time", t, {"units": "s"}), "node": [1, 2], "element": [1, 2]})
def offsets(figure):
    figure.canvas.draw()
    return [a.get_offset_text().get_text() for ax in figure.axes for a in (ax.xaxis, ax.yaxis)]
)";

TEST(PlotAxes, SeriesOfForcesAboveAMeganewtonAreInMeganewtonsWithoutOffsets) {
  const CliRun r = python("plot-axes-series", kRun + R"(
figure, what = p.draw_series(ds, SimpleNamespace(series=[], result="run.nc"))
c.plain_ticks(figure)
print(what, "|", *[ax.get_ylabel() for ax in figure.axes], sep=" ")
print("offsets:", repr("".join(offsets(figure))))
print(*[t.get_text() for t in figure.axes[0].get_yticklabels()])
print(*[t.get_text() for t in figure.axes[1].get_yticklabels()])
)");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 panels | max tension [MN] displacement magnitude [m]\n"
                          "offsets: ''\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("\n0.8 0.9 1 1.1 1.2 1.3 1.4 1.5 1.6\n"
                          "189.5 189.6 189.7 189.8 189.9 190 190.1 190.2 190.3 190.4 190.5\n"),
            std::string::npos)
      << r.output;
}

TEST(PlotAxes, SpectrumEndsWhereItsEnergyDoes) {
  const CliRun r = python("plot-axes-spectrum", kRun + R"(
figure, what = p.draw_spectrum(ds, SimpleNamespace(spectrum="tension_end@element=1,end=1",
                                                   start=100.0, segment=None))
c.plain_ticks(figure)
ax = figure.axes[0]
print("top %.3f" % ax.get_xlim()[1], "|", ax.get_ylabel(), "| offsets:",
      repr("".join(offsets(figure))))
omega = np.linspace(0.0, 10.0, 1001)
print("gauss %.4f" % c.energy_top(omega, np.exp(-0.5 * ((omega - 2.0) / 0.1) ** 2)))
print("flat %.4f" % c.energy_top(omega, np.ones_like(omega)))
)");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // A line at 0.6 rad/s under the Hann window of 125 s segments (bins of 2 pi / 125 s): 99.9% of
  // the energy up to bin 13 (0.6535 rad/s), the axis to 1.2 times that (before: to the Nyquist
  // frequency, 31.4 rad/s).
  EXPECT_NE(r.output.find("top 0.784 | spectral density [MN2 s rad-1] | offsets: ''\n"),
            std::string::npos)
      << r.output;
  // 99.9% of a Gaussian (mean 2, sigma 0.1) below 2 + 3.09 sigma = 2.309, times 1.2; a flat
  // spectrum to its end.
  EXPECT_NE(r.output.find("gauss 2.7720\nflat 10.0000\n"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace flexmoor::test
