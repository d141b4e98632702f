// The case-file reader's membranes: generated surfaces (node counts, merging, diagonal patterns,
// cables on cell boundaries, meridians with hoops), explicit membrane elements, pressures,
// histories and position-based node references, and the errors each reports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

using test::anyContains;
using test::joined;
using test::problems;
using test::writeCase;

// Materials and sections shared by the cases below, then `body`, then a static step.
std::string membraneCase(const std::string& body, const std::string& steps = "  - static: {}\n") {
  return R"(units: SI
materials:
  rubber: {type: mooney_rivlin, C1: 2.0e5, C2: 5.0e4}
  plastic: {type: linear_elastic, E: 1.0e9, nu: 0.3}
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  skin: {material: rubber, thickness: 0.001, density: 1100}
  film: {material: plastic, thickness: 0.0002}
  wire: {material: steel, area: 1.0e-5, density: 7850}
)" + body +
         "steps:\n" + steps;
}

int countType(const model::Model& m, const std::string& prefix) {
  return static_cast<int>(
      std::count_if(m.elements().begin(), m.elements().end(),
                    [&](const auto& e) { return e->typeName().rfind(prefix, 0) == 0; }));
}

TEST(CaseReaderSurfaces, RectangleOfQ8HasSerendipityNodeCount) {
  const Case c = readCase(writeCase("q8.yaml", membraneCase(R"(surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [2, 0, 0], side2: [0, 1, 0],
     divisions: [3, 2], element: Q8, section: skin}
supports:
  - {nodes: sheet, fix: [z]}
  - {nodes: {where: {x: 0}}, fix: [x, y]}
)")));
  // 4 x 3 corner nodes plus one node on each of the 3 x 3 + 4 x 2 = 17 cell edges.
  EXPECT_EQ(c.model->nodeCount(), 12 + 17);
  EXPECT_EQ(c.model->elementCount(), 6);
  EXPECT_EQ(countType(*c.model, "membrane8"), 6);
  ASSERT_EQ(c.element_sets.at("sheet").size(), 6u);
}

TEST(CaseReaderSurfaces, CentreDiagonalsMeetAtTheCentre) {
  const auto read = [](const std::string& diagonals) {
    return readCase(writeCase("t6-" + diagonals + ".yaml", membraneCase(R"(surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [2, 2], element: T6, diagonals: )" + diagonals + R"(, section: film}
supports:
  - {nodes: sheet, fix: [z]}
  - {nodes: {where: {x: 0}}, fix: [x, y]}
)")));
  };
  // The node at the centre of the square is a corner of all 8 triangles with `centre`
  // (Example 7's symmetric pattern), of 6 with diagonals all one way.
  for (const auto& [pattern, expected] :
       {std::pair<std::string, int>{"centre", 8}, {"forward", 6}}) {
    const Case c = read(pattern);
    ASSERT_EQ(c.model->elementCount(), 8) << pattern;
    EXPECT_EQ(c.model->nodeCount(), 25) << pattern;
    int centre = -1;
    for (int n = 0; n < c.model->nodeCount(); ++n)
      if ((c.model->reference().col(n) - Eigen::Vector3d(0.5, 0.5, 0)).norm() < 1e-12) centre = n;
    ASSERT_GE(centre, 0);
    int holding = 0;
    for (const auto& e : c.model->elements()) {
      const std::vector<int>& nodes = e->nodes();
      holding += std::find(nodes.begin(), nodes.begin() + 3, centre) != nodes.begin() + 3;
    }
    EXPECT_EQ(holding, expected) << pattern;
  }
}

TEST(CaseReaderSurfaces, ClosedCylinderSharesItsSeamNodes) {
  const Case c = readCase(writeCase("cyl.yaml", membraneCase(R"(surfaces:
  - {name: tube, shape: cylinder, centre: [0, 0, 0], radius: 2, length: 3, divisions: [8, 1],
     element: Q4, section: skin}
supports:
  - {nodes: tube, fix: [z]}
  - {nodes: {where: {z: 0}}, fix: [x, y]}
loads:
  pressure:
    - {on: tube, pressure: 1.0e3}
)")));
  EXPECT_EQ(c.model->nodeCount(), 16);  // 8 around x 2 rings: theta = 360 deg is theta = 0
  for (int n = 0; n < c.model->nodeCount(); ++n)
    EXPECT_NEAR(c.model->reference().col(n).head<2>().norm(), 2.0, 1e-12);
  ASSERT_EQ(c.model->pressures().size(), 1u);
  EXPECT_EQ(c.model->pressures()[0].elements.size(), 8u);
  EXPECT_DOUBLE_EQ(c.model->pressures()[0].pressure, 1.0e3);
}

TEST(CaseReaderSurfaces, DiscOfTrianglesCollapsesTheCentre) {
  const Case c = readCase(writeCase("disc.yaml", membraneCase(R"(surfaces:
  - {name: plate, shape: disc, centre: [0, 0, 1], radius: 4, angles: [0, 90 deg],
     divisions: [2, 4], element: T3, section: skin}
supports:
  - {nodes: plate, fix: [z]}
  - {nodes: {where: {x: 0}}, fix: [x]}
  - {nodes: {where: {y: 0}}, fix: [y]}
)")));
  // One centre node and 5 on each of the two rings; one triangle per inner cell, two per outer.
  EXPECT_EQ(c.model->nodeCount(), 11);
  EXPECT_EQ(c.model->elementCount(), 4 + 8);
  for (const auto& e : c.model->elements()) {
    const std::set<int> distinct(e->nodes().begin(), e->nodes().end());
    EXPECT_EQ(distinct.size(), 3u);
  }
}

TEST(CaseReaderSurfaces, CablesOnCellBoundariesShareTheMembraneEdgeNodes) {
  const Case c = readCase(writeCase("rings.yaml", membraneCase(R"(surfaces:
  - {name: tube, shape: cylinder, centre: [0, 0, 0], radius: 10, length: 15, angles: [0, 90 deg],
     divisions: [2, 2], element: Q8, section: skin,
     cables: [{along: around, at: [0, 1, 2], section: wire}]}
supports:
  - {nodes: {where: {x: 0}}, fix: [x]}
  - {nodes: {where: {y: 0}}, fix: [y]}
  - {nodes: tube, fix: [z]}
loads:
  pressure:
    - {on: tube, pressure: 1.0e3}
)")));
  EXPECT_EQ(countType(*c.model, "membrane8"), 4);
  EXPECT_EQ(countType(*c.model, "cable3"), 6);
  EXPECT_EQ(c.model->nodeCount(), 21);  // the cables add no nodes
  EXPECT_EQ(c.element_sets.at("tube").size(), 10u);
  EXPECT_EQ(c.model->pressures()[0].elements.size(), 4u);  // on the membranes only
  for (const auto& e : c.model->elements())
    if (e->typeName() == "cable3")
      for (int n : e->nodes()) {
        const double z = c.model->reference()(2, n);
        EXPECT_TRUE(z == 0.0 || std::abs(z - 7.5) < 1e-12 || std::abs(z - 15.0) < 1e-12) << z;
      }
}

TEST(CaseReaderSurfaces, MeridianFixesItsHoopDofsAndCarriesHoopCables) {
  const Case c = readCase(writeCase("meridian.yaml", membraneCase(R"(surfaces:
  - {name: wall, shape: meridian, from: [10, 0, 0], to: [10, 0, 30], elements: 4, order: 3,
     section: skin, cables: [{at: [0, 2, 4], section: wire}]}
supports:
  - {nodes: wall, fix: [z]}
)")));
  EXPECT_EQ(c.model->nodeCount(), 9);
  EXPECT_EQ(countType(*c.model, "axisymmetric_membrane3"), 4);
  EXPECT_EQ(countType(*c.model, "hoop_cable"), 3);
  for (int n = 0; n < c.model->nodeCount(); ++n) EXPECT_TRUE(c.model->isConstrained(n, 1));
}

TEST(CaseReaderSurfaces, SurfaceNodesMergeWithALineOnTheirEdge) {
  const Case c = readCase(writeCase("edge.yaml", membraneCase(R"(lines:
  - {name: edge, from: [0, 0, 0], to: [2, 0, 0], elements: 2, order: 3, section: wire}
surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [2, 0, 0], side2: [0, 1, 0],
     divisions: [2, 1], element: Q8, section: skin}
supports:
  - {nodes: sheet, fix: [z]}
  - {nodes: {where: {y: 1}}, fix: [x, y]}
)")));
  EXPECT_EQ(c.model->nodeCount(), 13);  // the Q8 mesh alone; the line's 5 nodes are on its edge
  EXPECT_EQ(c.lines.at("edge").size(), 5u);
}

TEST(CaseReaderSurfaces, ExplicitMembraneAndHoopElements) {
  const Case c = readCase(writeCase("explicit.yaml", membraneCase(R"(nodes:
  1: [0, 0, 0]
  2: [1, 0, 0]
  3: [1, 1, 0]
  4: [0, 1, 0]
  5: [3, 0, 0]
  6: [3, 0, 1]
elements:
  - {type: membrane, nodes: [1, 2, 3, 4], section: film}
  - {type: membrane, nodes: [1, 2, 3], section: film}
  - {type: axisymmetric_membrane, nodes: [5, 6], section: skin}
  - {type: hoop_cable, node: 6, section: wire}
supports:
  - {nodes: [1, 2, 3, 4], fix: [x, y, z]}
  - {nodes: [5], fix: [x, z]}
)")));
  EXPECT_EQ(c.model->element(0).typeName(), "membrane4");
  EXPECT_EQ(c.model->element(1).typeName(), "membrane3");
  EXPECT_EQ(c.model->element(2).typeName(), "axisymmetric_membrane2");
  EXPECT_EQ(c.model->element(3).typeName(), "hoop_cable");
  EXPECT_TRUE(c.model->isConstrained(c.model->nodeCount() - 1, 1));  // y of a meridian node
}

TEST(CaseReaderSurfaces, PositionReferencesFindTheirNodes) {
  const Case c = readCase(writeCase("at.yaml", membraneCase(R"(surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [2, 2], element: Q4, section: film}
node_sets:
  left: {where: {x: 0}}
  corner: [{at: [1, 1, 0]}]
supports:
  - {nodes: [left, {where: {y: 0}}], fix: [x, y, z]}
  - {nodes: sheet, fix: [z]}
summary:
  w: {quantity: displacement_x, node: {at: [1, 1, 0]}}
)")));
  ASSERT_EQ(c.node_sets.at("left").size(), 3u);
  for (int n : c.node_sets.at("left")) EXPECT_EQ(c.model->reference()(0, n), 0.0);
  const int corner = c.node_sets.at("corner").at(0);
  EXPECT_EQ(c.model->reference().col(corner), Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(c.summary.at(0).node, corner);
}

TEST(CaseReaderSurfaces, HistoriesDriveLoadsPressuresAndSupports) {
  const Case c = readCase(writeCase("histories.yaml", membraneCase(R"(surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [1, 1], element: Q4, section: film}
histories:
  wave: {type: sine, amplitude: 2, period: 4 s, phase: 0}
  start: {type: ramp, start: 1 s, duration: 2 s}
  gusts: {type: table, times: [0, 1 s, 3 s], values: [0, 1, -1]}
supports:
  - {nodes: {where: {x: 0}}, fix: [x, y, z]}
  - {nodes: {where: {x: 1}}, fix: [x], displacement: [0.01], history: start}
loads:
  nodal:
    - {node: {at: [1, 1, 0]}, force: [0, 0, 5], history: wave}
  pressure:
    - {on: sheet, pressure: 100, history: gusts}
)")));
  const model::Model& m = *c.model;
  ASSERT_EQ(m.nodalLoads().size(), 1u);
  ASSERT_TRUE(m.nodalLoads()[0].history);
  EXPECT_NEAR(m.nodalLoads()[0].history->value(1.0), 2.0, 1e-12);  // 2 sin(pi / 2)
  ASSERT_TRUE(m.pressures()[0].history);
  EXPECT_NEAR(m.pressures()[0].history->value(2.0), 0.0, 1e-12);  // halfway from 1 to -1
  int moved = 0;
  for (int n = 0; n < m.nodeCount(); ++n)
    if (const model::TimeFunction* f = m.motion(n, 0)) {
      ++moved;
      EXPECT_NEAR(f->value(2.0), 0.5, 1e-12);  // halfway up the ramp
      EXPECT_DOUBLE_EQ(m.prescribed(n, 0), 0.01);
    }
  EXPECT_EQ(moved, 2);
}

TEST(CaseReaderSurfaces, MembraneMistakesAreReportedWithTheirLines) {
  const std::vector<std::string> m =
      problems(writeCase("bad-membrane.yaml", membraneCase(R"(surfaces:
  - {name: plate, shape: disc, centre: [0, 0, 0], radius: 1, divisions: [2, 4], element: Q8, section: skin}
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [2, 0, 0],
     divisions: [1, 1], element: Q4, diagonals: centre, section: wire}
  - {name: roof, shape: rectangle, corner: [0, 0, 5], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [1, 1], element: Q4, section: skin}
lines:
  - {from: [0, 0, 0], to: [1, 0, 0], elements: 1, order: 2, section: skin}
elements:
  - {type: membrane, nodes: [1, 2, 3, 4, 5], section: skin}
  - {type: hoop_cable, node: {at: [0, 0, 5]}, section: wire}
histories:
  bumpy: {type: table, times: [0, 2, 1], values: [0, 1, 2]}
loads:
  pressure:
    - {on: lid, pressure: 1}
    - {on: roof, pressure: 1, history: calm}
)")));
  EXPECT_TRUE(anyContains(m, "bad-membrane.yaml:11: surfaces[1].element: a disc needs triangles"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "bad-membrane.yaml:12: surfaces[2]: side1 and side2 are parallel"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "surfaces[2].diagonals: only for triangles")) << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "surfaces[2].section: wrong kind of section (got 'wire', a cable "
                          "section with area, expected a membrane section with thickness)"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "lines[1].section: wrong kind of section (got 'skin'")) << joined(m);
  EXPECT_TRUE(anyContains(m, "elements[1].nodes: no membrane has 5 nodes")) << joined(m);
  EXPECT_TRUE(anyContains(m, "elements[2].node: a hoop needs a radius")) << joined(m);
  EXPECT_TRUE(anyContains(m, "histories.bumpy.times: not increasing")) << joined(m);
  EXPECT_TRUE(anyContains(m, "loads.pressure[1].on: unknown surface (got 'lid'")) << joined(m);
  EXPECT_TRUE(anyContains(m,
                          "loads.pressure[2].history: unknown history (got 'calm', expected "
                          "one of: bumpy)"))
      << joined(m);
}

TEST(CaseReaderSurfaces, LinearElasticWithoutPoissonRatioIsNotAMembraneMaterial) {
  const std::vector<std::string> m = problems(writeCase("no-nu.yaml", R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  plate: {material: steel, thickness: 0.01}
steps:
  - static: {}
)"));
  EXPECT_TRUE(anyContains(m,
                          "no-nu.yaml:5: sections.plate.material: not a membrane material "
                          "(got 'steel', linear_elastic without nu"))
      << joined(m);
}

TEST(CaseReaderSurfaces, WhereWithoutMatchingNodesIsAnError) {
  const std::vector<std::string> m = problems(writeCase("nowhere.yaml", membraneCase(R"(surfaces:
  - {name: sheet, shape: rectangle, corner: [0, 0, 0], side1: [1, 0, 0], side2: [0, 1, 0],
     divisions: [1, 1], element: Q4, section: film}
supports:
  - {nodes: {where: {x: 7}}, fix: [x, y, z]}
  - {node: {at: [0.5, 0.5, 0]}, fix: [z]}
)")));
  EXPECT_TRUE(anyContains(m, "supports[1].nodes.where: no node matches")) << joined(m);
  EXPECT_TRUE(anyContains(m, "supports[2].node.at: no node there")) << joined(m);
}

}  // namespace
}  // namespace flexmoor::app
