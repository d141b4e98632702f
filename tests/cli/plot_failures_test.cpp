// `flexmoor plot` never shows a traceback (apps/plot/flexmoor_plot.py): a series the file does
// not hold is named (exit 2), the default figure draws what the file has, -o into a directory
// that is not there creates it, and any other failure is one line with exit 4; a run whose
// figure cannot be drawn keeps its results and exit code 0 and says why on stderr.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;

// A taut wire plucked at its middle, 40 time steps; `output` is the case's output: block (or
// nothing) and `figure` its figure: block (or nothing).
std::string wireCase(const std::string& name, const std::string& output,
                     const std::string& figure) {
  return "name: " + name + R"(
title: a taut wire plucked at its middle
units: SI
materials:
  steel: {type: linear_elastic, E: 200 GPa}
sections:
  wire: {material: steel, area: 1 cm^2, density: 7850 kg/m^3}
lines:
  - {name: cable, from: [0, 0, 0], to: [10 m, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01 m, 0, 0]}
  - {nodes: cable, fix: [y]}
histories:
  pluck: {type: sine, amplitude: 1, period: 0.2 s}
loads:
  nodal:
    - {node: cable.middle, force: [0, 0, 100 N], history: pluck}
steps:
  - static: {}
  - dynamic: {dt: 0.005 s, steps: 40}
)" + output +
         figure;
}

// Runs the wire writing only `fields` into a scratch directory; returns its netCDF.
fs::path runWriting(const std::string& scratch_name, const std::string& fields) {
  const fs::path dir = scratch(scratch_name);
  const CliRun r =
      runText(dir, "wire", wireCase("wire", "output: {fields: [" + fields + "]}\n", ""));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return dir / "wire.nc";
}

void expectNoTraceback(const CliRun& r) {
  EXPECT_EQ(r.errors.find("Traceback"), std::string::npos) << r.errors;
  EXPECT_EQ(r.errors.find("File \""), std::string::npos) << r.errors;
}

// A directory holding a Python package `matplotlib` whose import raises `error`: on PYTHONPATH
// it stands in for Debian's, so that drawing fails the way a broken installation would.
fs::path brokenMatplotlib(const fs::path& dir, const std::string& error) {
  fs::create_directories(dir / "matplotlib");
  std::ofstream(dir / "matplotlib" / "__init__.py") << "raise " << error << "\n";
  return dir;
}

TEST(PlotFailures, DefaultFigureOfARunWithoutDisplacementsDrawsItsTension) {
  const fs::path nc = runWriting("plot-fail-tension", "tension");
  const fs::path png = nc.parent_path() / "default.png";
  const CliRun r = flexmoor("plot " + nc.string() + " -o " + png.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote " + png.string() + " (1 panel)"), std::string::npos) << r.output;
  EXPECT_NE(r.errors.find("flexmoor plot: the default figure leaves out the displacement of the "
                          "node that moves most (no displacement_x, _y, _z)"),
            std::string::npos)
      << r.errors;
  EXPECT_GT(pngSize(png).first, 0u);
  expectNoTraceback(r);
}

TEST(PlotFailures, DefaultFigureOfARunWithNeitherIsRefusedNamingTheSeriesItHas) {
  const fs::path nc = runWriting("plot-fail-position", "position");
  const fs::path png = nc.parent_path() / "default.png";
  const CliRun r = flexmoor("plot " + nc.string() + " -o " + png.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.errors.find("flexmoor plot: the default figure draws the largest end tension and "
                          "the displacement of the node that moves most, and the file has "
                          "neither tension_end nor displacement_x, _y, _z"),
            std::string::npos)
      << r.errors;
  EXPECT_NE(r.errors.find("(the file's: position_x, position_y, position_z)"), std::string::npos)
      << r.errors;
  EXPECT_FALSE(fs::exists(png));
  expectNoTraceback(r);
}

TEST(PlotFailures, SpeedWithoutVelocitiesOrAnIndexTheVariableLacksIsRefused) {
  const fs::path nc = runWriting("plot-fail-speed", "position, tension");
  const fs::path png = nc.parent_path() / "speed.png";
  const CliRun speed =
      flexmoor("plot " + nc.string() + " -o " + png.string() + " --series speed@node=3");
  EXPECT_EQ(speed.exit_code, 2) << speed.output;
  EXPECT_NE(speed.errors.find("flexmoor plot: speed is |velocity| and needs velocity_x, _y and "
                              "_z; the file does not hold velocity_x, velocity_y, velocity_z "
                              "(the case's output: fields: leaves out velocity)"),
            std::string::npos)
      << speed.errors;
  expectNoTraceback(speed);
  const CliRun index =
      flexmoor("plot " + nc.string() + " -o " + png.string() + " --series position_x@element=2");
  EXPECT_EQ(index.exit_code, 2) << index.output;
  EXPECT_NE(index.errors.find("flexmoor plot: position_x has no element index (its dimensions: "
                              "time, node)"),
            std::string::npos)
      << index.errors;
  expectNoTraceback(index);
  EXPECT_FALSE(fs::exists(png));
}

TEST(PlotFailures, OutputIntoADirectoryNotThereCreatesIt) {
  const fs::path nc = runWriting("plot-fail-directory", "displacement, tension");
  const fs::path png = nc.parent_path() / "figures" / "of" / "wire.png";
  const CliRun r = flexmoor("plot " + nc.string() + " -o " + png.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_GT(pngSize(png).first, 0u);
  // A file where the directory would be, and a directory given as the PNG: named, no figure.
  std::ofstream(nc.parent_path() / "blocked") << "a file\n";
  const CliRun blocked = flexmoor("plot " + nc.string() + " -o " +
                                  (nc.parent_path() / "blocked" / "wire.png").string());
  EXPECT_EQ(blocked.exit_code, 4) << blocked.output;
  EXPECT_NE(
      blocked.errors.find("cannot create the directory " + (nc.parent_path() / "blocked").string() +
                          " (a file of that name is in the way)"),
      std::string::npos)
      << blocked.errors;
  const CliRun directory = flexmoor("plot " + nc.string() + " -o " + nc.parent_path().string());
  EXPECT_EQ(directory.exit_code, 2) << directory.output;
  EXPECT_NE(directory.errors.find(" is a directory (expected the PNG file to write"),
            std::string::npos)
      << directory.errors;
  // A refused figure creates no directory.
  const CliRun refused =
      flexmoor("plot " + nc.string() + " -o " + (nc.parent_path() / "refused" / "x.png").string() +
               " --series buoy_x@node=1");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_FALSE(fs::exists(nc.parent_path() / "refused"));
  expectNoTraceback(blocked);
  expectNoTraceback(directory);
}

TEST(PlotFailures, AnyOtherFailureIsOneLineWithExitCode4) {
  const fs::path nc = runWriting("plot-fail-internal", "displacement, tension");
  const fs::path dir = nc.parent_path();
  const fs::path broken = brokenMatplotlib(dir / "broken", "RuntimeError('a broken\\nmatplotlib')");
  const CliRun r = command("PYTHONPATH=" + broken.string() + " " + FLEXMOOR_BINARY + " plot " +
                           nc.string() + " -o " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_EQ(r.errors,
            "flexmoor plot: internal error, the figure was not drawn (RuntimeError: a "
            "broken matplotlib)\n");
  const fs::path missing = brokenMatplotlib(
      dir / "missing", "ImportError('No module named pyparsing', name='pyparsing')");
  const CliRun m = command("PYTHONPATH=" + missing.string() + " " + FLEXMOOR_BINARY + " plot " +
                           nc.string() + " -o " + (dir / "x.png").string());
  EXPECT_EQ(m.exit_code, 4) << m.output;
  EXPECT_EQ(m.errors,
            "flexmoor plot: cannot import pyparsing (No module named pyparsing): it "
            "needs Debian's python3-matplotlib and python3-xarray (scripts/setup.sh "
            "installs them)\n");
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(PlotFailures, ARunWhoseFigureCannotBeDrawnKeepsItsResultsAndSaysWhy) {
  const fs::path dir = scratch("plot-fail-run");
  const std::string figure = "figure:\n  series:\n    - {quantity: tension_end, element: 1}\n";
  std::ofstream(dir / "wire.yaml") << wireCase("wire", "", figure);
  const fs::path broken = brokenMatplotlib(dir / "broken", "RuntimeError('a broken matplotlib')");
  const CliRun r = command("PYTHONPATH=" + broken.string() + " " + FLEXMOOR_BINARY + " run " +
                           (dir / "wire.yaml").string() + " -o " + dir.string() + " --no-vtk");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "wire.nc"));
  EXPECT_TRUE(fs::exists(dir / "wire.summary.json"));
  EXPECT_FALSE(fs::exists(dir / "wire.png"));
  EXPECT_FALSE(fs::exists(dir / ".wire.tmp.png"));
  EXPECT_NE(r.errors.find("flexmoor plot: internal error, the figure was not drawn "
                          "(RuntimeError: a broken matplotlib)\n"
                          "flexmoor: the figure " +
                          (dir / "wire.png").string() +
                          " was not drawn (flexmoor plot exited with 4; its message is above); "
                          "the results are complete\n"),
            std::string::npos)
      << r.errors;
  EXPECT_EQ(r.output.find("figure:  "), std::string::npos) << r.output;
  expectNoTraceback(r);
}

}  // namespace
}  // namespace flexmoor::test
