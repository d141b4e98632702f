// The static step of a case with waves solves in still water (gravity, buoyancy, current), as
// MoorDyn, MAP++ and OrcaFlex take their statics: one chain's fairlead tension under a 4 m, 10 s
// wave equals the same case's without waves (reference: that run; 1e-9 relative, round-off of
// the same solve), and `waves: frozen` takes the wave as it stands at t = 0 instead (it moved the
// tension by 0.17% on such a line before statics were still: held to differ by more than 1e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "tests/support/in_process_run.hpp"

namespace flexmoor::test {
namespace {

const char* kChain = R"(scenario: spread_mooring
units: SI
water: {density: 1025 kg/m^3, depth: 100 m}
line_types:
  chain: {diameter: 0.1 m, mass_per_length: 200 kg/m, EA: 8e8 N, Cn: 1.6, Ct: 0.1, Ca: 1.0}
mooring_lines:
  - {anchor: [500, 0, -100 m], fairlead: [20, 0, -10 m], length: 520 m, type: chain}
)";

double fairleadTension(const std::string& name, const std::string& text) {
  const InProcessRun r = runCaseInProcess(name, text);
  EXPECT_EQ(r.exit_code, app::kSuccess) << r.log;
  return r.value("fairlead_tension_static_1");
}

TEST(StillWaterStatics, WavesStayOutOfTheEquilibriumUnlessFrozen) {
  const std::string waves = "waves:\n  components:\n    - {height: 4 m, period: 10 s}\n";
  const double calm = fairleadTension("calm-chain", kChain);
  const double still = fairleadTension("still-chain", std::string(kChain) + waves);
  const double frozen =
      fairleadTension("frozen-chain", std::string(kChain) + waves + "statics: {waves: frozen}\n");
  EXPECT_NEAR(still / calm, 1.0, 1e-9);
  EXPECT_GT(std::abs(frozen / calm - 1.0), 1e-4);
  std::cout << "[ StillWaterStatics ] calm " << calm << " N, frozen wave " << frozen << " N\n";
}

}  // namespace
}  // namespace flexmoor::test
