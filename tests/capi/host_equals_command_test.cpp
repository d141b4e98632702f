// Check CA6. The example host (examples/c/platform_host.c) drives OC4's platform through the C
// API step by step with the case's own motion; its results file equals `flexmoor run`'s of the
// same case to the last bit in every variable (reference: the command's file; tolerance 0). The
// case is oc4-semi-surge cut to 120 s.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

TEST(CApiHost, DrivesOc4AsTheCommandRunsItToTheBit) {
  const std::filesystem::path dir = scratch("capi-host-oc4");
  std::string text =
      readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/ocean/oc4-semi-surge.yaml");
  const size_t at = text.find("steps: 6000");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 11, "steps: 1200");
  std::ofstream(dir / "oc4-120s.yaml") << text;
  const CliRun cli = flexmoor("run " + (dir / "oc4-120s.yaml").string() + " -o " +
                              (dir / "command").string() + " --no-figure");
  ASSERT_EQ(cli.exit_code, 0) << cli.output;
  const CliRun host =
      command(std::string(FLEXMOOR_PLATFORM_HOST) + " " + (dir / "oc4-120s.yaml").string() +
              " -o " + (dir / "host").string() + " --duration 120");
  ASSERT_EQ(host.exit_code, 0) << host.output;
  const CliRun same = command(
      "/usr/bin/python3 " + std::string(FLEXMOOR_SOURCE_DIR) + "/tests/capi/same_netcdf.py " +
      (dir / "command" / "oc4-120s.nc").string() + " " + (dir / "host" / "oc4-120s.nc").string());
  EXPECT_EQ(same.exit_code, 0) << same.output;
}

}  // namespace
}  // namespace flexmoor::test
