// The checks of the built model (apps/case/check/model_checks.cpp): what `check` must refuse
// because `run` would fail on it or report a wrong number, each with the line that defines the
// element, node, support or step; and the warnings for what runs but perhaps not as meant.
// The catalogue tests/bad_inputs/ has one file per class for the command line; these tests go
// through the reader and state the exact Jacobians of the kernels.
#include <gtest/gtest.h>

#include <string>

#include "apps/case/case_reader.hpp"
#include "apps/case/input/diagnostics.hpp"
#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::app {
namespace {

using test::anyContains;
using test::joined;
using test::problems;
using test::writeCase;

// A header shared by the cases below: steel wire (lines 1-5).
const std::string kWire = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4, density: 7850}
)";

// Line L of file F, as the messages name it.
std::string at(const std::string& file, int line) {
  return file + ":" + std::to_string(line) + ":";
}

// A quadratic cable with its middle node at fraction t of its chord from the first node.
double quadraticCableJacobian(double t) {
  model::NodalField X(3, 3);
  X << 0.0, 10.0 * t, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0;
  const auto e = element::makeCableElement({0, 1, 2}, element::CableSection{1e-4, 0.0, nullptr});
  return e->minRelativeJacobian(X);
}

// Reference: x(xi) = sum L^I X^I with the middle node at t L gives
// dx/dxi = L (xi (1 - 2t) + 1/2), least at an end: L min(2t - 1/2, 3/2 - 2t), relative to D / 2
// with D = L max(1, t) the bounding diagonal. Exact up to round-off (1e-12).
TEST(ElementJacobian, QuadraticCableFollowsItsMiddleNode) {
  EXPECT_NEAR(quadraticCableJacobian(0.5), 1.0, 1e-12);   // evenly spaced
  EXPECT_NEAR(quadraticCableJacobian(0.4), 0.6, 1e-12);   // still one to one
  EXPECT_NEAR(quadraticCableJacobian(0.25), 0.0, 1e-12);  // quarter point: singular at the end
  EXPECT_NEAR(quadraticCableJacobian(0.0), -1.0, 1e-12);  // middle on the first end
  EXPECT_NEAR(quadraticCableJacobian(1.2), -1.5, 1e-12);  // beyond the last end: folded
}

// Reference: the unit square as a Q4 has X,1 = e1 / 2, X,2 = e2 / 2, area element 1/4, bounding
// diagonal sqrt(2): relative Jacobian 0.25 / (sqrt(2) / 2)^2 = 0.5 at every point. Swapping two
// nodes makes a bow-tie of two equal lobes of opposite orientation: no mean normal, 0. With one
// corner moved out to (2, 2) the lobes differ and the area element is negative at the Gauss
// points of the smaller one. A right triangle of legs 1 has area element 1 (natural area 1/2):
// 1 / (sqrt(2) / 2)^2 = 2. Collinear nodes give 0.
TEST(ElementJacobian, MembranesKnowTheirOrientation) {
  const element::MembraneSection section{1e-3, 0.0, nullptr};
  model::NodalField X(3, 4);
  X << 0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0;
  EXPECT_NEAR(element::makeMembraneElement("quad", {0, 1, 2, 3}, section)->minRelativeJacobian(X),
              0.5, 1e-12);
  const auto bow_tie = element::makeMembraneElement("quad", {0, 1, 3, 2}, section);
  EXPECT_NEAR(bow_tie->minRelativeJacobian(X), 0.0, 1e-12);
  model::NodalField stretched = X;
  stretched.col(2) << 2.0, 2.0, 0.0;
  EXPECT_LT(bow_tie->minRelativeJacobian(stretched), 0.0);
  EXPECT_NEAR(element::makeMembraneElement("triangle", {0, 1, 3}, section)->minRelativeJacobian(X),
              2.0, 1e-12);
  model::NodalField line(3, 3);
  line << 0, 1, 2, 0, 0, 0, 0, 0, 0;
  EXPECT_NEAR(
      element::makeMembraneElement("triangle", {0, 1, 2}, section)->minRelativeJacobian(line), 0.0,
      1e-12);
}

// Reference: a 2-node meridian from r = 1 to r = 3 (length 2 along x, bounding diagonal 2) has
// dX/dxi . e = 1, relative 1; its smallest radius at the 3 Gauss points is 2 - sqrt(3/5), relative
// (2 - 0.7746) / 2 = 0.6127. Moved to cross the axis (r from -1 to 1), that radius is negative.
TEST(ElementJacobian, AxisymmetricMeridianNeedsAPositiveRadius) {
  const element::MembraneSection section{1e-3, 0.0, nullptr};
  const auto e = element::makeAxisymmetricMembrane({0, 1}, section);
  model::NodalField X(3, 2);
  X << 1, 3, 0, 0, 0, 0;
  EXPECT_NEAR(e->minRelativeJacobian(X), (2.0 - std::sqrt(0.6)) / 2.0, 1e-12);
  X << -1, 1, 0, 0, 0, 0;
  EXPECT_LT(e->minRelativeJacobian(X), 0.0);
}

TEST(ModelChecks, DegenerateCableIsRefusedWithItsLine) {
  const std::string file = writeCase("folded.yaml", kWire + R"(nodes:
  1: [0, 0, 0]
  2: [0, 0, 0]
  3: [10, 0, 0]
elements:
  - {type: cable, nodes: [1, 2, 3], section: wire}
supports:
  - {nodes: [1, 3], fix: [x, y, z]}
  - {node: 2, fix: [y]}
steps:
  - static: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 11) + " element 1 (cable3 of elements[1]): folded"))
      << joined(messages);
}

TEST(ModelChecks, CurvedButOneToOneElementsPass) {
  // A quadratic cable bowed to a semicircle (middle node at the top) and a Q8 quarter of a
  // cylinder are curved, not degenerate.
  const Case c = readCase(writeCase("curved.yaml", kWire + R"(nodes:
  1: [-1, 0, 0]
  2: [0, 0, 1]
  3: [1, 0, 0]
elements:
  - {type: cable, nodes: [1, 2, 3], section: wire}
supports:
  - {nodes: [1, 3], fix: [x, y, z]}
  - {node: 2, fix: [y]}
steps:
  - static: {}
)"));
  EXPECT_EQ(c.model->elementCount(), 1);
}

TEST(ModelChecks, BowTieAndZeroAreaMembranesAreRefused) {
  const std::string file = writeCase("bowtie.yaml", R"(units: SI
materials:
  rubber: {type: linear_elastic, E: 1.0e6, nu: 0.3}
sections:
  sheet: {material: rubber, thickness: 0.001}
nodes:
  1: [0, 0, 0]
  2: [1, 0, 0]
  3: [1, 1, 0]
  4: [0, 1, 0]
  5: [2, 0, 0]
elements:
  - {type: membrane, nodes: [1, 2, 4, 3], section: sheet}
  - {type: membrane, nodes: [1, 2, 3, 4], section: sheet}
  - {type: membrane, nodes: [1, 2, 5], section: sheet}
supports:
  - {nodes: [1, 2, 4, 5], fix: [x, y, z]}
  - {node: 3, fix: [z]}
steps:
  - static: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 2u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 13) + " element 1 (membrane4")) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 15) + " element 3 (membrane3")) << joined(messages);
}

TEST(ModelChecks, StructureWithoutSupportsIsAMechanism) {
  const std::string file = writeCase("free.yaml", kWire + R"(lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 4, order: 2, section: wire}
steps:
  - relax: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 7) + " line 'cable' (5 nodes) is free to move in "
                                                  "x, y, z as a rigid body"))
      << joined(messages);
}

TEST(ModelChecks, TautCableNetIsNotAMechanism) {
  // Straight cables pinned at their ends have no initial lateral stiffness, but no rigid motion:
  // relaxation is for them. A line from an explicit node, pinned at both ends.
  const Case c = readCase(writeCase("net.yaml", kWire + R"(nodes:
  1: [-10, 0, 0]
lines:
  - {name: a, start_node: 1, to: [10, 0, 0], elements: 2, order: 2, section: wire}
supports:
  - {nodes: [a.start, a.end], fix: [x, y, z]}
steps:
  - relax: {}
)"));
  EXPECT_TRUE(c.warnings.empty());
}

TEST(ModelChecks, UnmergedNodesAreAnErrorWhenTheyLeaveAMechanismAndAWarningElse) {
  const std::string nodes = R"(nodes:
  1: [0, 0, 0]
  2: [5, 0, 0]
  3: [5, 0, 0]
  4: [5, 0, -3]
elements:
  - {type: cable, nodes: [1, 2], section: wire}
  - {type: cable, nodes: [3, 4], section: wire}
)";
  const std::string file = writeCase("hanger.yaml", kWire + nodes + R"(supports:
  - {nodes: [1, 2], fix: [x, y, z]}
steps:
  - relax: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 9) + " node 3 and the node joined to it"))
      << joined(messages);
  EXPECT_TRUE(anyContains(messages, "node 3 is at the same point as node 2 (line 8)"))
      << joined(messages);
  // Both parts supported: the model runs, and the pair is reported as a warning.
  const Case c = readCase(writeCase("hanger-held.yaml", kWire + nodes + R"(supports:
  - {nodes: [1, 2, 4], fix: [x, y, z]}
steps:
  - relax: {}
)"));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find(":8: warning: node 2 and node 3 (line 9) are at one point"),
            std::string::npos)
      << c.warnings[0];
}

TEST(ModelChecks, ModesWithoutDensityNameTheStepAndTheSection) {
  const std::string file = writeCase("massless.yaml", R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4}
lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01, 0, 0]}
steps:
  - static: {}
  - modes: {count: 2}
  - dynamic: {dt: 0.01, steps: 2}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 2u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 13) + " step 'modes': needs a mass on every free "
                                                   "dof, and 9 have none"))
      << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 14) + " step 'dynamic'")) << joined(messages);
  EXPECT_TRUE(anyContains(messages, "got no density: on section wire")) << joined(messages);
}

TEST(ModelChecks, MoreModesThanFreeDofsAreRefused) {
  const std::string file = writeCase("modes.yaml", kWire + R"(lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 2, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01, 0, 0]}
steps:
  - static: {}
  - modes: {count: 4}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 13) + " step 'modes': more modes than free dofs "
                                                   "(got count: 4, expected at most 3)"))
      << joined(messages);
}

TEST(ModelChecks, SpringOfRestLengthZeroIsRefused) {
  const std::string file = writeCase("spring.yaml", R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [1, 0, 0]
elements:
  - {type: point_mass, node: 2, mass: 1}
  - {type: spring, nodes: [1, 2], stiffness: 100, rest_length: 0 m}
supports:
  - {node: 1, fix: [x, y, z]}
  - {node: 2, fix: [y, z]}
steps:
  - static: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 7) + " elements[2].rest_length: a spring of rest "
                                                  "length 0 has no direction when it is at rest "
                                                  "(got 0 m, expected > 0)"))
      << joined(messages);
}

TEST(ModelChecks, ADofPrescribedTwiceDifferentlyIsRefusedAndTwiceAlikeIsNot) {
  const std::string head = kWire + R"(lines:
  - {name: cable, from: [0, 0, 0], to: [10, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {nodes: cable, fix: [y]}
  - {nodes: [cable.start, cable.end], fix: [x, y, z]}
)";
  const std::string file =
      writeCase("twice.yaml", head + R"(  - {node: cable.end, fix: [x], displacement: [0.01]}
steps:
  - static: {}
)");
  const auto messages = problems(file);
  ASSERT_EQ(messages.size(), 1u) << joined(messages);
  EXPECT_TRUE(anyContains(messages, at(file, 11) + " supports[3]: node 5 x is prescribed twice, "
                                                   "differently (got 0.01 here and 0 on line 10"))
      << joined(messages);
  // y fixed twice at 0 (by the first two supports) is one prescription.
  EXPECT_NO_THROW(readCase(writeCase("alike.yaml", head + "steps:\n  - static: {}\n")));
}

// The demo case's forcing (a 0.5 s sine) under a 1000 s time step: it runs, with a warning that
// gives dt / period = 2000.
const char* kLongStep = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4, density: 7850}
lines:
  - {name: cable, from: [0, 0, 0], to: [10 m, 0, 0], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [0.01 m, 0, 0]}
  - {nodes: cable, fix: [y]}
histories:
  shake: {type: sine, amplitude: 1, period: 0.5 s}
loads:
  nodal:
    - {node: cable.middle, force: [0, 0, 10 N], history: shake}
steps:
  - static: {}
  - dynamic: {name: shake, dt: 1000 s, steps: 2}
)";

TEST(ModelChecks, TimeStepLongerThanItsForcingIsAWarning) {
  const std::string file = writeCase("long-step.yaml", kLongStep);
  const Case c = readCase(file);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.warnings[0], file +
                               ":19: warning: step 'shake': dt = 1000 s is 2000 times the period "
                               "0.5 s of history 'shake' (dt / period = 2000; fewer than 10 steps "
                               "a period do not resolve it, expected dt <= 0.05 s)");
  // The demo's own schedule (5 and 10 ms for the 0.5 s period) warns of nothing.
  EXPECT_TRUE(readCase(resolveCasePath("driven-taut-cable")).warnings.empty());
}

TEST(ModelChecks, CheckPrintsWarningsAndStillSucceeds) {
  const std::string file = writeCase("long-step-cli.yaml", kLongStep);
  const test::CliRun r = test::flexmoor("check " + file);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("flexmoor: " + file + ":19: warning: step 'shake': dt = 1000 s"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("valid"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace flexmoor::app
