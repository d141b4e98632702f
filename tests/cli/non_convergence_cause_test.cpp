// Runs that cannot converge say why (exit 3), naming the likely cause and where: a load beyond
// what the structure carries (load control and arc length) and the dof that moves most. (A
// mechanism under load: tests/verification/solver_diagnosis_test.cpp, in code, since `check`
// refuses such a case file.) Numbers in %g style: no "%f" padding such as
// "6.000000" or "0.000000".
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

// Example 3's Mooney-Rivlin tube (axisymmetric, 2 quadratic elements), whose internal pressure can
// never exceed 2 (C1 + C2) h0 / R = 5.16 psf (the stretch runs to infinity as it nears it),
// pressurised to 6 psf by `step`.
std::string burstingTube(const std::string& step) {
  return R"(units: US
materials:
  rubber: {type: mooney_rivlin, C1: 2300 psf, C2: 280 psf}
sections:
  skin: {material: rubber, thickness: 0.01 ft}
surfaces:
  - {name: tube, shape: meridian, from: [10 ft, 0, 0], to: [10 ft, 0, 30 ft], elements: 2,
     order: 3, section: skin}
supports:
  - {nodes: tube, fix: [z]}
loads:
  pressure:
    - {on: tube, pressure: 1 psf}
steps:
  - )" + step +
         R"(
summary:
  radial: {quantity: displacement_x, node: {at: [10 ft, 0, 0]}}
)";
}

CliRun runText(const std::string& name, const std::string& text) {
  return test::runText(scratch(name + "-" + std::to_string(getpid())), name, text);
}

void expectDiagnosis(const CliRun& r, const std::vector<std::string>& fragments) {
  EXPECT_EQ(r.exit_code, 3) << r.output;
  for (const std::string& f : fragments)
    EXPECT_NE(r.output.find(f), std::string::npos) << "missing '" << f << "' in\n" << r.output;
  EXPECT_EQ(r.output.find("000000"), std::string::npos) << r.output;
}

// Load control past the limit pressure: Newton gets nowhere at 6 psf.
TEST(NonConvergence, LoadControlPastTheLimitLoadSaysSo) {
  const CliRun r = runText("burst-load", burstingTube("static: {load_factor: 6, increments: 2, "
                                                      "pressure_stiffness: true}"));
  expectDiagnosis(
      r, {"increment 2 of 2 (load factor 6) did not converge",
          "the load may exceed what the structure carries", "in equilibrium at load factor 3",
          "the largest displacement increment", "is at node"});
}

// Arc length past the limit pressure. Unchecked, the path runs away to a radius of 5e16 ft,
// where the residual's round-off floor passes anything, "lands" on load factor 6 and exits 0
// with that radius in summary.json. It stops where the displacements pass 1000 times the
// model's size and names the limit: 5.16 (the closed form, to the 3 digits printed).
TEST(NonConvergence, ArcLengthThatRunsAwayNamesTheLimitLoad) {
  const CliRun r = runText("burst-arc", burstingTube("static: {load_factor: 6, increments: 5, "
                                                     "control: arc_length, "
                                                     "pressure_stiffness: true}"));
  expectDiagnosis(r, {"arc-length path runs away", "cannot carry load factor 6",
                      "the most it carries is about 5.16 times the reference load"});
}

// Newmark: a stiff spring pendulum (1 kg on 1e4 N/m, released from the horizontal) allowed one
// Newton iteration per step against a tolerance of 1e-10 fails even after two halvings; the
// message gives the iterations' course and the dof that moved most.
TEST(NonConvergence, TimeStepFailureGivesTheIterationsAndWhere) {
  const CliRun r = runText("pendulum-cut", R"(units: SI
nodes:
  1: [0, 0, 0]
  7: [1 m, 0, 0]
elements:
  - {type: spring, nodes: [1, 7], stiffness: 1e4 N/m, compression: carry}
  - {type: point_mass, node: 7, mass: 1 kg}
supports:
  - {node: 1, fix: [x, y, z]}
  - {node: 7, fix: [y]}
loads:
  gravity: {g: 9.81 m/s^2}
steps:
  - dynamic: {dt: 0.05 s, steps: 20, max_iterations: 1, tolerance: 1e-10, max_step_cuts: 2}
)");
  expectDiagnosis(r, {"did not converge even with dt = 0.0125 s",
                      "the largest displacement "
                      "increment of the last iteration",
                      "is at node 7 "});
}

}  // namespace
}  // namespace flexmoor::test
