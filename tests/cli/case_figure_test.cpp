// A case's figure: (apps/case/read/read_figure.cpp, apps/run/draw_figure.cpp): a run draws
// DIR/<case>.png of the series it names, says where, and leaves no figure of an earlier run that
// it did not draw (--no-figure, or a case without figure:).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

const std::string kCase = R"(name: figure-case
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
)";

const std::string kFigure = R"(figure:
  series:
    - {quantity: position_z, node: cable.middle}
    - {quantity: speed, node: cable.middle}
    - {quantity: tension_end, element: 1, end: 1}
)";

bool isPng(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  char header[8] = {};
  in.read(header, sizeof header);
  return in && std::string(header, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}

TEST(CaseFigure, ARunDrawsTheCasesFigureAndSaysWhere) {
  const auto dir = scratch("case-figure");
  const CliRun r = runText(dir, "figure-case", kCase + kFigure);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto png = dir / "figure-case.png";
  EXPECT_TRUE(isPng(png));
  EXPECT_GT(std::filesystem::file_size(png), 20000u);  // three panels of curves, not a blank
  EXPECT_NE(r.output.find("figure:  " + png.string()), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / ".figure-case.tmp.png"));
}

TEST(CaseFigure, ARunThatDrawsNoFigureLeavesNoneOfAnEarlierRun) {
  const auto dir = scratch("case-figure-stale");
  ASSERT_EQ(runText(dir, "figure-case", kCase + kFigure).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(dir / "figure-case.png"));
  const CliRun again = flexmoor("run " + (dir / "figure-case.yaml").string() + " -o " +
                                dir.string() + " --no-figure");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "figure-case.png"));
  EXPECT_EQ(again.output.find("figure:"), std::string::npos);
}

}  // namespace
}  // namespace flexmoor::test
