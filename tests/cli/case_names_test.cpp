// A case named on the command line (apps/case/case_reader.cpp, resolveCasePath): a mistyped name
// is refused with the nearest names (exit 2, nothing run), and a path or name without `.yaml`
// resolves, for `run`, `check` and `study` alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;

void expectRefused(const CliRun& r, const std::string& message) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(r.errors, "flexmoor: " + message + "\n");
}

TEST(CaseNames, AMistypedNameSuggestsTheNearest) {
  const fs::path dir = scratch("case-names-typo");
  expectRefused(flexmoor("check oc4-semi-surg"),
                "no case 'oc4-semi-surg'; did you mean 'oc4-semi-surge'?");
  expectRefused(flexmoor("run oc4-semi-surg -o " + dir.string()),
                "no case 'oc4-semi-surg'; did you mean 'oc4-semi-surge'?");
  expectRefused(flexmoor("study tube-rao-bse -o " + dir.string()),
                "no case 'tube-rao-bse'; did you mean 'tube-rao-base'?");
  expectRefused(flexmoor("check oc3-hywind"),
                "no case 'oc3-hywind'; did you mean 'oc3-hywind-statics' or 'oc3-hywind-surge'?");
  const CliRun far = flexmoor("check no-such-thing");
  EXPECT_EQ(far.exit_code, 2) << far.output;
  EXPECT_EQ(far.errors.find("flexmoor: no case 'no-such-thing' (no such file, nor a case of that "
                            "name; available: chain-wire-chain-motion, "),
            0u)
      << far.errors;
  const std::string ocean = std::string(FLEXMOOR_SOURCE_DIR) + "/cases/ocean/";
  expectRefused(flexmoor("check " + ocean + "oc4-semi-surg.yaml"),
                "no case file '" + ocean + "oc4-semi-surg.yaml'; did you mean '" + ocean +
                    "oc4-semi-surge.yaml'?");
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(CaseNames, APathOrNameWithoutYamlResolves) {
  const std::string file =
      std::string(FLEXMOOR_SOURCE_DIR) + "/cases/seed/ex1-suspended-cable-8xL2";
  const CliRun path = flexmoor("check " + file);
  EXPECT_EQ(path.exit_code, 0) << path.output;
  EXPECT_EQ(path.output.find(file + ".yaml: valid"), 0u) << path.output;
  const CliRun name = flexmoor("check ex1-suspended-cable-8xL2.yaml");
  EXPECT_EQ(name.exit_code, 0) << name.output;
  EXPECT_EQ(name.output.find(file + ".yaml: valid"), 0u) << name.output;
  const fs::path dir = scratch("case-names-path");
  const CliRun run = flexmoor("run " + file + " -o " + dir.string() + " --no-vtk");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "ex1-suspended-cable-8xL2.summary.json"));
}

}  // namespace
}  // namespace flexmoor::test
