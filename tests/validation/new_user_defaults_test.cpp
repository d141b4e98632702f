// Cases written from the README alone, with no solver keys, converge without cutting a step and
// to the answer of a much tighter Newton: three chains in 100 m of water under a 3 m, 12 s surge
// (its platform motion ramped in over one period, the default), and one chain in a 4 m, 10 s
// regular wave. Reference: the same case with residual_tolerance 1e-12 and tolerance 1e-10
// (the default's 1e-8 and 1e-6 tightened a hundred- and ten-thousandfold); metric: the fairlead
// tension's maximum and minimum over the run, relative; tolerance 1e-7 (measured 2.3e-8 for the
// three chains, 5e-12 for the one in a wave).
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "tests/support/in_process_run.hpp"

namespace flexmoor::test {
namespace {

const char* kWater = R"(scenario: spread_mooring
units: SI
water: {density: 1025 kg/m^3, depth: 100 m}
line_types:
  chain: {diameter: 0.1 m, mass_per_length: 200 kg/m, EA: 8e8 N, Cn: 1.6, Ct: 0.1, Ca: 1.0}
)";

const char* kThreeChains = R"(mooring_lines:
  - {anchor: [500, 0, -100 m], fairlead: [20, 0, -10 m], length: 520 m, type: chain}
  - {anchor: [-250, 433.0127, -100 m], fairlead: [-10, 17.3205, -10 m], length: 520 m, type: chain}
  - {anchor: [-250, -433.0127, -100 m], fairlead: [-10, -17.3205, -10 m], length: 520 m, type: chain}
platform:
  surge: {amplitude: 3 m, period: 12 s}
)";

const char* kOneChainInAWave = R"(waves:
  components:
    - {height: 4 m, period: 10 s}
mooring_lines:
  - {anchor: [500, 0, -100 m], fairlead: [20, 0, -10 m], length: 520 m, type: chain}
)";

const char* kSummary = R"(summary:
  t_max: {quantity: end_tension, element: 20, end: last, stat: max}
  t_min: {quantity: end_tension, element: 20, end: last, stat: min}
)";

struct Run {
  double max = 0.0, min = 0.0;
  std::string log;
};

Run run(const std::string& name, const std::string& text) {
  const InProcessRun r = runCaseInProcess(name, text);
  EXPECT_EQ(r.exit_code, app::kSuccess) << r.log;
  return {r.value("t_max"), r.value("t_min"), r.log};
}

void expectConvergedDefaults(const std::string& name, const std::string& lines, int steps) {
  const std::string dynamic = "dynamic: {dt: 0.05 s, steps: " + std::to_string(steps);
  const Run plain = run(name, kWater + lines + dynamic + "}\n" + kSummary);
  const Run tight =
      run(name + "-tight",
          kWater + lines + dynamic + ", residual_tolerance: 1e-12, tolerance: 1e-10}\n" + kSummary);
  EXPECT_NE(plain.log.find(" 0 step cuts"), std::string::npos) << plain.log;
  EXPECT_NEAR(plain.max / tight.max, 1.0, 1e-7) << name;
  EXPECT_NEAR(plain.min / tight.min, 1.0, 1e-7) << name;
  std::cout << "[ NewUserDefaults ] " << name << ": max " << plain.max / tight.max - 1.0 << ", min "
            << plain.min / tight.min - 1.0 << "\n";
}

TEST(NewUserDefaults, ThreeChainsUnderASurgeConvergeWithoutCuts) {
  expectConvergedDefaults("three-chains", kThreeChains, 1200);
}

TEST(NewUserDefaults, AChainInARegularWaveConvergesWithoutCuts) {
  expectConvergedDefaults("chain-in-a-wave", kOneChainInAWave, 600);
}

}  // namespace
}  // namespace flexmoor::test
