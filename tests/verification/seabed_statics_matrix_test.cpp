// Statics that never fail on a seabed: one heavy chain (390 kg/m, 0.25 m, EA 2e9 N, as MoorDyn's
// chain validation decks) in 200 m of water, started on its catenary with the laid part exactly
// on the bed, solved by the default static step for every element order (2, 3 and 4 nodes), 5 to
// 200 elements, beds from 1e4 to 1e9 Pa/m, and three lines: slack (a laid part), taut (lifting
// off at the anchor) and fully laid (the fairlead on the bed too). Each must converge with the
// residual verified (|R|/S < 1e-8, the default Convergence) and its fairlead tension agree with
// the rigid-bed elastic catenary (tests/support/mooring_catenary, written apart from flexmoor),
// within what the bed's give and the mesh allow (tolerances per case below, each just above the
// measured deviation); the fully laid line carries no tension but its end's share of the weight.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "tests/support/in_process_run.hpp"
#include "tests/support/mooring_catenary.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);

struct Line {
  const char* name;
  double span, fairlead_z, length;
};

// w = (390 - 1025 pi 0.25^2 / 4) 9.80665 N/m
double submergedWeight() { return (390.0 - 1025.0 * kPi * 0.25 * 0.25 / 4.0) * 9.80665; }

std::string chainCase(const Line& line, int order, int elements, double bed) {
  std::ostringstream s;
  s << "scenario: spread_mooring\nunits: SI\n"
    << "water: {density: 1025 kg/m^3, depth: 200 m}\n"
    << "seabed: {stiffness: " << bed << " Pa/m, damping: 3.0e5 Pa*s/m}\n"
    << "line_types:\n  chain: {diameter: 0.25 m, mass_per_length: 390 kg/m, EA: 2.0e9 N,\n"
    << "          Cn: 1.6, Ct: 0.1, Ca: 1.0}\n"
    << "mooring_lines:\n  - {anchor: [" << line.span << ", 0, -200 m], fairlead: [0, 0, "
    << line.fairlead_z << " m], length: " << line.length
    << " m, type: chain, elements: " << elements << ", order: " << order << "}\n";
  return s.str();
}

struct Outcome {
  bool converged = false;
  double tension = 0.0;
  std::string log;
};

Outcome solve(const Line& line, int order, int elements, double bed) {
  const std::string name = std::string("chain-") + line.name + "-" + std::to_string(order) + "-" +
                           std::to_string(elements) + "-" + std::to_string(int(std::log10(bed)));
  const InProcessRun r = runCaseInProcess(name, chainCase(line, order, elements, bed));
  Outcome out;
  out.converged = r.exit_code == app::kSuccess;
  out.log = r.log;
  if (out.converged) out.tension = r.value("fairlead_tension_static_1");
  return out;
}

TEST(SeabedStatics, EveryMeshOnEveryBedConvergesToTheCatenary) {
  const Line slack{"slack", 1000.0, -20.0, 1100.0}, taut{"taut", 900.0, -20.0, 925.0};
  const double w = submergedWeight();
  for (const Line& line : {slack, taut}) {
    const double T = solveMooringLine({line.span, 200.0 + line.fairlead_z, line.length, w, 2.0e9})
                         .fairlead_tension();
    for (const int order : {2, 3, 4})
      for (const int elements : {5, 41, 76, 200})
        for (const double bed : {1e4, 1e6, 1e9}) {
          const Outcome o = solve(line, order, elements, bed);
          const std::string what = std::string(line.name) + ", " + std::to_string(elements) +
                                   " elements of " + std::to_string(order) + " nodes, bed " +
                                   std::to_string(bed);
          ASSERT_TRUE(o.converged) << what << "\n" << o.log;
          EXPECT_NE(o.log.find("equilibrium at load factor 1"), std::string::npos) << what;
          // The coarsest mesh (220 m elements) converges but is no catenary: measured -57% for
          // L2, 7% for L3, 2.4% for L4. From 41 elements on, the rigid-bed catenary within 3.5e-3
          // (measured 3.1e-3) on beds of 1e6 Pa/m and up, and within 1e-2 on 1e4 Pa/m, where the
          // laid chain sinks w / (k d) = 1.3 m (measured 8.3e-3).
          const double tolerance = elements == 5 ? 0.6 : bed < 1e5 ? 1e-2 : 3.5e-3;
          EXPECT_NEAR(o.tension / T, 1.0, tolerance) << what;
          std::cout << "[ SeabedStatics ] " << what << ": " << o.tension / T - 1.0 << "\n";
        }
  }
}

// A chain of submerged weight w and axial stiffness EA laid on a bed of stiffness k_f = k_b d per
// length between two ends pinned at the bed's level, L apart: away from the ends it sinks
// delta = w / k_f; near each it rises to the pin as z = -delta (1 - exp(-x / lambda)),
// lambda = sqrt(H / k_f) (H z'' = k_f z + w). The rise lengthens the chain by delta^2 / (4 lambda)
// at each end (small slopes), which its stretch H L / EA takes up:
// H^(3/2) = EA delta^2 sqrt(k_f) / (2 L); the pin pulls up V = H delta / lambda.
double laidChainTension(double w, double EA, double k_f, double L) {
  const double delta = w / k_f;
  const double H = std::pow(EA * delta * delta * std::sqrt(k_f) / (2.0 * L), 2.0 / 3.0);
  return std::hypot(H, delta * std::sqrt(H * k_f));
}

// A line lying straight on the bed, both ends at the bed's level and no slack, for every order,
// 5 to 200 elements and beds of 1e4, 1e6 and 1e9 Pa/m: every one converges. On the soft bed the
// rise at the ends (lambda = 12 m) is resolved from 41 elements on, and the fairlead tension is
// the foundation's closed form, 0.277 w L (measured -1.8%, -1.2%, -0.12% for 41 elements of 2, 3,
// 4 nodes; -0.57%, -0.26%, -0.07% for 76; -0.15%, -0.08%, -0.07% for 200). On stiffer beds no mesh
// resolves the rise (lambda = 12 cm, 0.1 mm) and the fairlead carries its share of the end
// element's weight (measured 0.29, 0.12 and 0.06 of an element's weight for 2, 3 and 4 nodes on
// 1e9 Pa/m), held below half an element's weight and the closed form's tension (3.7 kN on 1e6
// Pa/m, 4 N on 1e9; measured at most 0.50 of an element's weight with 200 L4 on 1e6, where the
// closed form is 0.55 of one). The hardest, 76 cubic elements on 1e9 Pa/m: Newton stalls near
// 2e-6 (the laid chain has no stiffness across the bed), and viscous relaxation from the start,
// then Newton, reach the round-off floor of the bed's stiffness.
TEST(SeabedStatics, AFullyLaidLineCarriesOnlyItsEndsWeight) {
  const Line laid{"laid", 400.0, -200.0, 400.0};
  const double w = submergedWeight();
  for (const int order : {2, 3, 4})
    for (const int elements : {5, 41, 76, 200})
      for (const double bed : {1e4, 1e6, 1e9}) {
        const Outcome o = solve(laid, order, elements, bed);
        const std::string what = std::to_string(elements) + " elements of " +
                                 std::to_string(order) + " nodes, bed " + std::to_string(bed);
        ASSERT_TRUE(o.converged) << what << "\n" << o.log;
        const double element_weight = w * 400.0 / elements;
        const double foundation = laidChainTension(w, 2.0e9, bed * 0.25, 400.0);
        if (bed > 1e5) {
          EXPECT_LT(o.tension, 0.5 * element_weight + foundation) << what;
        } else if (elements > 5) {
          const double tolerance = elements == 41 ? 2e-2 : elements == 76 ? 6e-3 : 2e-3;
          EXPECT_NEAR(o.tension / foundation, 1.0, tolerance) << what;
        }
        std::cout << "[ SeabedStatics ] laid " << what << ": " << o.tension / element_weight
                  << " element weights, " << o.tension / foundation - 1.0
                  << " from the foundation's closed form\n";
      }
}

}  // namespace
}  // namespace flexmoor::test
