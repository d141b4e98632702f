// The case-file reader: valid files build the expected model, steps and summary; invalid ones are
// refused with every problem at once, each with its line and what was expected.
#include "apps/case/case_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "apps/case/input/diagnostics.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/common/format_number.hpp"
#include "libstruct/element/cable_element.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

using test::anyContains;
using test::joined;
using test::problems;
using test::writeCase;

const char* kExampleOne = R"(# Example 1, 8 linear elements
name: ex1-test
title: Example 1 in a test
units: US
materials:
  steel: {type: linear_elastic, E: 1.0e6 psf, compression: carry}
sections:
  main: {material: steel, area: 0.1 ft^2, density: 0.031056 slug/ft^3, quadrature: 0}
lines:
  - {name: cable, from: [0, 0, 0], to: [200 ft, 0, 0], elements: 8, order: 2, section: main}
supports:
  - {nodes: all, fix: [y]}
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [z]}
loads:
  gravity: [0, 0, -32.2 ft/s^2]
  nodal:
    - {node: cable.end, force: [5.8 lbf, 0, 0]}
steps:
  - relax: {tolerance: 0.001, damping: 10000, initial_damping_factor: 0.01, decrement: 1.0, max_steps: 500, residual_tolerance: 1e-8, load_factor: 1.0}
summary:
  center_sag: {quantity: displacement_z, node: cable.middle, scale: -1}
  support_movement: {quantity: displacement_x, node: cable.end, scale: -1}
  anchor_tension: {quantity: reaction_magnitude, node: cable.start}
  max_tension: {quantity: max_tension}
  top_tension: {quantity: end_tension, element: 8, end: last}
)";

TEST(CaseReader, BuildsExampleOneFromALine) {
  const Case c = readCase(writeCase("ex1.yaml", kExampleOne));
  EXPECT_EQ(c.name, "ex1-test");
  EXPECT_EQ(c.title, "Example 1 in a test");
  EXPECT_EQ(c.units, UnitSystem::US);
  const model::Model& m = *c.model;
  EXPECT_EQ(m.nodeCount(), 9);
  EXPECT_EQ(m.elementCount(), 8);
  EXPECT_EQ(m.equationCount(), 27 - 9 - 2 - 1);  // y everywhere, x z at the pin, z at the roller
  EXPECT_DOUBLE_EQ(m.reference()(0, 8), 200.0);
  EXPECT_DOUBLE_EQ(m.reference()(0, 4), 100.0);
  EXPECT_DOUBLE_EQ(m.gravity().z(), -32.2);
  ASSERT_EQ(m.nodalLoads().size(), 1u);
  EXPECT_EQ(m.nodalLoads()[0].node, 8);
  EXPECT_DOUBLE_EQ(m.nodalLoads()[0].force.x(), 5.8);
  const auto* cable = dynamic_cast<const element::CableElement<2>*>(&m.element(0));
  ASSERT_NE(cable, nullptr);
  EXPECT_DOUBLE_EQ(cable->section().area, 0.1);
  EXPECT_DOUBLE_EQ(cable->section().density, 0.031056);
  EXPECT_EQ(cable->section().material->compression(), material::Compression::Carry);
  EXPECT_EQ(c.lines.at("cable").size(), 9u);

  ASSERT_EQ(c.steps.size(), 1u);
  EXPECT_EQ(c.steps[0].kind, StepSpec::Kind::Relax);
  EXPECT_EQ(c.steps[0].name, "relax");
  EXPECT_EQ(c.steps[0].where.line, 20);
  EXPECT_DOUBLE_EQ(c.steps[0].relax.damping, 10000.0);
  EXPECT_DOUBLE_EQ(c.steps[0].relax.initial_damping_factor, 0.01);
  EXPECT_EQ(c.steps[0].relax.max_steps, 500);

  ASSERT_EQ(c.summary.size(), 5u);
  EXPECT_EQ(c.summary[0].name, "center_sag");
  EXPECT_EQ(c.summary[0].quantity, SummarySpec::Quantity::Displacement);
  EXPECT_EQ(c.summary[0].node, 4);
  EXPECT_EQ(c.summary[0].component, 2);
  EXPECT_DOUBLE_EQ(c.summary[0].scale, -1.0);
  EXPECT_EQ(c.summary[0].step, -1);
  EXPECT_EQ(c.summary[0].unit, "ft");
  EXPECT_EQ(c.summary[2].quantity, SummarySpec::Quantity::ReactionMagnitude);
  EXPECT_EQ(c.summary[2].unit, "lbf");
  EXPECT_EQ(c.summary[4].element, 7);
  EXPECT_EQ(c.summary[4].end, 1);
}

TEST(CaseReader, ExplicitNodesElementsAndLinesShareIds) {
  const Case c = readCase(writeCase("mixed.yaml", R"(units: SI
materials:
  rope: {type: mooney_rivlin, C1: 24 psi, C2: 3 psi, compression: carry}
sections:
  rope: {material: rope, area: 1 cm^2, density: 1000 kg/m^3, quadrature: 3}
nodes:
  3: [10, 0, 0]
  1: [0, 0, 0]
lines:
  - {name: a, start_node: 1, to: [0, 0, -6 m], elements: 2, order: 3, section: rope}
  - {name: b, start_node: a.end, end_node: 3, elements: 1, order: 4, section: rope}
elements:
  - {type: spring, nodes: [3, a.middle], stiffness: 100 N/m, compression: carry}
  - {type: point_mass, node: a.end, mass: 2 kg}
  - {type: cable, nodes: [1, 3], section: rope}
node_sets:
  anchors: [1, 3]
supports:
  - {nodes: anchors, fix: [y, z]}
  - {nodes: all, fix: [y]}
  - {node: 1, fix: [x]}
  - {node: 3, fix: [x], displacement: [0.5 m]}
loads:
  gravity: {g: 9.81 m/s^2}
  nodal:
    - {nodes: [a.end, a.end], force: [0, 0, -10 N]}
steps:
  - static: {increments: 4, newton: modified, stiffness_update: 2, tolerance: 1e-5, criterion: residual, name: settle}
  - relax: {damping: 10 N/m, max_steps: 20}
summary:
  sag: {quantity: displacement_z, node: a.end, scale: -1, step: settle}
  anchor: {quantity: reaction_magnitude, node: 1}
  spring: {quantity: end_tension, element: 1, end: last}
  top: {quantity: end_tension, element: 4, end: first}
  peak: {quantity: max_tension, step: 2}
)"));
  EXPECT_EQ(c.name, "mixed");  // the file's stem
  const model::Model& m = *c.model;
  // Explicit ids 1, 3 first; line a adds 4..7 after node 1; line b adds 8, 9 between 7 and 3.
  EXPECT_EQ(c.node_ids, (std::vector<int>{1, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(c.lines.at("a"), (std::vector<int>{0, 2, 3, 4, 5}));
  EXPECT_EQ(c.lines.at("b"), (std::vector<int>{5, 6, 7, 1}));
  EXPECT_EQ(m.nodeCount(), 8);
  EXPECT_DOUBLE_EQ(m.reference()(2, 6), -4.0);
  // Explicit elements first (spring, point mass, cable), then lines a (2) and b (1).
  ASSERT_EQ(m.elementCount(), 6);
  EXPECT_EQ(m.element(0).typeName(), "spring");
  EXPECT_EQ(m.element(0).nodes(), (std::vector<int>{1, 3}));
  EXPECT_EQ(m.element(1).typeName(), "point_mass");
  EXPECT_EQ(m.element(3).nodes(), (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(m.element(5).nodes(), (std::vector<int>{5, 6, 7, 1}));
  const auto* cable = dynamic_cast<const element::CableElement<3>*>(&m.element(3));
  ASSERT_NE(cable, nullptr);
  EXPECT_DOUBLE_EQ(cable->section().area, 1e-4);
  EXPECT_EQ(cable->section().material->name(), "mooney_rivlin");

  EXPECT_EQ(c.node_sets.at("anchors"), (std::vector<int>{0, 1}));
  EXPECT_EQ(m.equationCount(), 24 - 6 - 6);
  EXPECT_DOUBLE_EQ(m.prescribed(1, 0), 0.5);
  EXPECT_DOUBLE_EQ(m.gravity().z(), -9.81);
  ASSERT_EQ(m.nodalLoads().size(), 1u);  // a node named twice is loaded once
  EXPECT_EQ(m.nodalLoads()[0].node, 5);

  ASSERT_EQ(c.steps.size(), 2u);
  const solve::StaticOptions& s = c.steps[0].statics;
  EXPECT_EQ(c.steps[0].name, "settle");
  EXPECT_EQ(s.increments, 4);
  EXPECT_EQ(s.flavour, solve::NewtonFlavour::Modified);
  EXPECT_EQ(s.stiffness_update, 2);
  EXPECT_DOUBLE_EQ(s.convergence.displacement_tolerance, 1e-5);
  EXPECT_FALSE(s.convergence.use_displacement);
  EXPECT_TRUE(s.convergence.use_residual);
  EXPECT_DOUBLE_EQ(c.steps[1].relax.damping, 10.0);
  EXPECT_EQ(c.steps[1].relax.max_steps, 20);

  ASSERT_EQ(c.summary.size(), 5u);
  EXPECT_EQ(c.summary[0].node, 5);
  EXPECT_EQ(c.summary[0].step, 0);
  EXPECT_EQ(c.summary[0].unit, "m");
  EXPECT_EQ(c.summary[1].unit, "N");
  EXPECT_EQ(c.summary[2].element, 0);
  EXPECT_EQ(c.summary[3].element, 3);
  EXPECT_EQ(c.summary[4].step, 1);
}

TEST(CaseReader, ReportsEveryErrorWithItsLine) {
  const std::vector<std::string> m = problems(writeCase("bad.yaml", R"(name: bad
units: US
materials:
  steel: {type: linear_elastic, E: -1.0e6 psf}
sections:
  main: {material: steel, area: 0.1 ft, density: 0.031056 slug/ft^3}
lines:
  - {name: cable, from: [0, 0, 0], to: [200 ft, 0, 0], elements: 8, order: 5, section: main}
supports:
  - {node: 42, fix: [x, w]}
steps:
  - static: {increments: 0, newton: ful}
summary:
  sag: {quantity: displacement_z, node: cable.middle}
)"));
  // What refers to the broken material, section and line is not reported again.
  ASSERT_EQ(m.size(), 7u) << joined(m);
  EXPECT_NE(m[0].find("bad.yaml:4: materials.steel.E: out of range"), std::string::npos) << m[0];
  EXPECT_NE(m[1].find("bad.yaml:6: sections.main.area: wrong unit: expected an area, got 'ft'"),
            std::string::npos)
      << m[1];
  EXPECT_NE(m[2].find("bad.yaml:8: lines[1].order: out of range (got 5, expected 2 to 4)"),
            std::string::npos)
      << m[2];
  EXPECT_TRUE(anyContains(m, "bad.yaml:10: supports[1].node: unknown node (got 42")) << joined(m);
  EXPECT_TRUE(anyContains(m, "bad.yaml:10: supports[1].fix[2]: unknown value (got 'w'"))
      << joined(m);
  EXPECT_TRUE(anyContains(m, "bad.yaml:12: steps[1].static.increments: out of range (got 0"))
      << joined(m);
  EXPECT_TRUE(
      anyContains(m,
                  "bad.yaml:12: steps[1].static.newton: unknown value (got 'ful', "
                  "expected one of: full, modified, bfgs, self_corrective; did you mean 'full'?)"))
      << joined(m);
}

TEST(CaseReader, NegativeModulusReportsGotAndExpected) {
  const std::vector<std::string> m = problems(writeCase("negative.yaml", R"(units: US
materials:
  steel: {type: linear_elastic, E: -1.0e6 psf}
)"));
  EXPECT_TRUE(anyContains(m,
                          "negative.yaml:3: materials.steel.E: out of range "
                          "(got -1.0e6 psf, expected > 0)"))
      << joined(m);
}

TEST(CaseReader, UnknownKeyIsReportedWithTheAllowedKeys) {
  const std::vector<std::string> m =
      problems(writeCase("typo.yaml", std::string(kExampleOne) + R"(elments:
  - {type: point_mass, node: 5, mass: 1 slug}
)"));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("typo.yaml:27: unknown key 'elments' (expected one of: name, title, units,"),
            std::string::npos)
      << m[0];
  EXPECT_NE(m[0].find("did you mean 'elements'?"), std::string::npos) << m[0];
}

// An unknown key that is not the last of its map must not shift every later key onto its
// successor's value (std::remove_if assigning YAML::Node over YAML::Node rebinds the node in
// the document): one typo would give a cascade of bogus errors. One mistake, one message.
TEST(CaseReader, MisspelledFirstKeyOfAMapIsTheOnlyProblem) {
  std::string text = kExampleOne;
  text.replace(text.find("relax: {tolerance:"), 18, "relax: {tolerence:");
  const std::vector<std::string> m = problems(writeCase("first.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("first.yaml:20: steps[1].relax: unknown key 'tolerence'"), std::string::npos)
      << m[0];
  EXPECT_NE(m[0].find("did you mean 'tolerance'?"), std::string::npos) << m[0];
}

TEST(CaseReader, MisspelledMiddleKeyOfAMapIsTheOnlyProblem) {
  std::string text = kExampleOne;
  text.replace(text.find(" damping: 10000"), 15, " dampng: 10000");
  const std::vector<std::string> m = problems(writeCase("middle.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("middle.yaml:20: steps[1].relax: unknown key 'dampng'"), std::string::npos)
      << m[0];
}

// The same through Fields itself: every known key after an unknown one keeps its own value, and
// the document is left as it was read.
TEST(CaseReader, KeysAfterAnUnknownOneKeepTheirOwnValues) {
  for (const char* text : {"{typo: 0, a: 1, b: 2, c: 3}", "{a: 1, typo: 0, b: 2, c: 3}",
                           "{a: 1, b: 2, typo: 0, c: 3}"}) {
    const YAML::Node map = YAML::Load(text);
    Diagnostics diag("fields.yaml");
    const Fields f(diag, map, "m", {"a", "b", "c"});
    EXPECT_EQ(diag.messages().size(), 1u) << text;
    int expected = 1;
    for (const char* key : {"a", "b", "c"}) {
      ASSERT_NE(f.find(key), nullptr) << text << " " << key;
      EXPECT_EQ(f.find(key)->Scalar(), std::to_string(expected)) << text << " " << key;
      EXPECT_EQ(map[key].Scalar(), std::to_string(expected)) << text << " " << key;
      ++expected;
    }
    EXPECT_EQ(map["typo"].Scalar(), "0") << text;
  }
}

// Numbers in messages: %g style (reference: printf's %.10g), never %f's fixed decimals.
TEST(Diagnostics, NumbersInMessagesAreInGStyle) {
  EXPECT_EQ(formatNumber(1e13), "1e+13");
  EXPECT_EQ(formatNumber(0.0), "0");
  EXPECT_EQ(formatNumber(0.1 + 0.2), "0.3");
  EXPECT_EQ(formatNumber(-32.2), "-32.2");
  EXPECT_EQ(formatNumber(1.0000001), "1.0000001");
  EXPECT_EQ(formatNumber(2.5e-9), "2.5e-09");
}

TEST(CaseReader, RepeatedKeyIsReported) {
  const std::vector<std::string> m = problems(writeCase("repeat.yaml", R"(units: US
units: SI
)"));
  EXPECT_TRUE(anyContains(m, "repeat.yaml:2: units: repeated key (first given on line 1)"))
      << joined(m);
}

TEST(CaseReader, MissingRequiredKeysAreReported) {
  const std::vector<std::string> m = problems(writeCase("empty.yaml", "title: nothing\n"));
  EXPECT_TRUE(anyContains(m, "empty.yaml:1: missing key 'units'")) << joined(m);
  EXPECT_TRUE(anyContains(m, "empty.yaml:1: missing key 'steps'")) << joined(m);
}

TEST(CaseReader, MiddleOfALineWithAnEvenNodeCountIsAnError) {
  std::string text = kExampleOne;
  text.replace(text.find("elements: 8"), 11, "elements: 7");
  text.replace(text.find("element: 8"), 10, "element: 7");
  const std::vector<std::string> m = problems(writeCase("even.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("even.yaml:22: summary.center_sag.node: line 'cable' has no middle node "
                      "(got 8 nodes, expected an odd number)"),
            std::string::npos)
      << m[0];
}

TEST(CaseReader, ReactionAtAFreeDofIsRefused) {
  std::string text = kExampleOne;
  const std::string anchor = "{quantity: reaction_magnitude, node: cable.start}";
  text.replace(text.find(anchor), anchor.size(), "{quantity: reaction_x, node: cable.middle}");
  const std::vector<std::string> m = problems(writeCase("free.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("free.yaml:24: summary.anchor_tension.node: the reaction is zero (got a "
                      "node whose x is free, expected a fixed dof)"),
            std::string::npos)
      << m[0];
}

TEST(CaseReader, UnconnectedFreeNodeIsRefused) {
  std::string text = kExampleOne;
  text += "nodes:\n  100: [0, 5, 0]\n";
  text.replace(text.find("{nodes: all, fix: [y]}"), 22, "{nodes: cable, fix: [y]}");
  const std::vector<std::string> m = problems(writeCase("loose.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("loose.yaml:28: node 100: no element holds it"), std::string::npos) << m[0];
}

TEST(CaseReader, YamlSyntaxErrorIsReportedWithItsLine) {
  const std::vector<std::string> m =
      problems(writeCase("syntax.yaml", "units: US\nmaterials:\n  steel: {type: [\n"));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("syntax.yaml:"), std::string::npos);
  EXPECT_NE(m[0].find("not valid YAML"), std::string::npos) << m[0];
}

TEST(CaseReader, CaseErrorPrefixesEveryLineWithTheCommand) {
  try {
    readCase(writeCase("two.yaml", "units: USA\nsteps: []\n"));
    FAIL() << "an invalid case was accepted";
  } catch (const CaseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.messages().size(), 2u) << what;  // the unit system, no steps
    const std::string second = what.substr(what.find('\n') + 1);
    EXPECT_EQ(what.rfind("flexmoor: ", 0), 0u) << what;
    EXPECT_NE(what.find("two.yaml:1: units: unknown value (got 'USA'"), std::string::npos) << what;
    EXPECT_EQ(second.rfind("flexmoor: ", 0), 0u) << what;
    EXPECT_NE(second.find("two.yaml:2: steps: no steps"), std::string::npos) << what;
  }
}

TEST(CaseReader, ResolvesNamedCasesAndListsThem) {
  const std::string path = resolveCasePath("ex1-suspended-cable-4xL3");
  EXPECT_EQ(fs::path(path).filename(), "ex1-suspended-cable-4xL3.yaml");
  const Case c = readCase(path);
  EXPECT_EQ(c.model->nodeCount(), 9);
  EXPECT_EQ(c.model->elementCount(), 4);
  EXPECT_EQ(resolveCasePath(path), path);  // an existing path as it is

  const auto cases = listCases();
  const auto found = std::find_if(cases.begin(), cases.end(), [](const auto& entry) {
    return entry.first == "ex1-suspended-cable-8xL2";
  });
  ASSERT_NE(found, cases.end());
  EXPECT_NE(found->second.find("Example 1"), std::string::npos) << found->second;
}

// A name near none of the cases lists the available ones; a near one is suggested (the nearest
// by edit distance).
TEST(CaseReader, UnknownCaseNameListsTheAvailableOnesOrSuggestsTheNearest) {
  try {
    resolveCasePath("no-such-case");
    FAIL() << "an unknown case was resolved";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ex1-suspended-cable-8xL2"), std::string::npos)
        << e.what();
  }
  try {
    resolveCasePath("ex1-suspended-cable-8xL3");
    FAIL() << "an unknown case was resolved";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ex1-suspended-cable-8xL2"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexmoor::app
