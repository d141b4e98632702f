#include "tests/support/wire_in_a_sea.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "tests/support/cli_run.hpp"
#include "tests/support/submerged_wire.hpp"

namespace flexmoor::test {

std::filesystem::path runWireInASea(const std::string& name, int steps) {
  const std::filesystem::path dir = scratch(name + "-" + std::to_string(getpid()));
  std::ofstream(dir / "wire.yaml") << "units: SI\ntitle: a wire in a JONSWAP sea\n"
                                   << submergedWire("0.01 m") << R"(waves:
  spectrum: {type: jonswap, Hs: 2 m, Tp: 8 s}
  components: 50
  discretisation: equal
  seed: 77
steps:
  - relax: {name: r}
  - dynamic: {name: d, dt: 0.25 s, steps: )"
                                   << steps << "}\n";
  const CliRun r = flexmoor("run " + (dir / "wire.yaml").string() + " -o " + dir.string() +
                            " --no-vtk --no-figure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(" 0 step cuts"), std::string::npos) << r.output;
  return dir / "wire.nc";
}

}  // namespace flexmoor::test
