// Figures a person reads: `flexmoor plot` (apps/plot/flexmoor_plot.py with Debian's matplotlib
// under the system interpreter) draws time series of a run's netCDF as a PNG, and refuses a
// series it cannot find.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

using flexmoor::test::flexmoor;

flexmoor::test::CliRun plot(const std::string& args) { return flexmoor("plot " + args); }

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23), 0 if not a PNG.
std::pair<uint32_t, uint32_t> pngSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature, signature + 8, header)) return {0, 0};
  const auto word = [&](int at) {
    return uint32_t(header[at]) << 24 | uint32_t(header[at + 1]) << 16 |
           uint32_t(header[at + 2]) << 8 | uint32_t(header[at + 3]);
  };
  return {word(16), word(20)};
}

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

}  // namespace
