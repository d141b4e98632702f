// A case stated in code (CaseSpec, buildCase) and the same case read from its YAML build the same
// model and give the same results, to the bit: Example 1's cable of 8 linear elements, relaxed
// under gravity and a pull at its roller (cases/seed/ex1-suspended-cable-8xL2.yaml with its
// values in the case's units, without unit names: a value converted from "psf" moves by an ulp).
// And what the specifications get wrong is refused with its reason.
#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>

#include "apps/case/build/build_case.hpp"
#include "apps/case/case_reader.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/material/cable_material.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/twin_runs.hpp"

namespace flexmoor::test {
namespace {

const char* kExample1 = R"(name: ex1-twin
units: US
materials:
  cable: {type: linear_elastic, E: 1000000, compression: carry}
sections:
  cable: {material: cable, area: 0.1, density: 0.031056}
lines:
  - {name: cable, from: [0, 0, 0], to: [200, 0, 0], elements: 8, order: 2, section: cable}
supports:
  - {nodes: all, fix: [y]}
  - {node: cable.start, fix: [x, z]}
  - {node: cable.end, fix: [z]}
loads:
  gravity: [0, 0, -32.2]
  nodal:
    - {node: cable.end, force: [5.8, 0, 0]}
steps:
  - relax: {tolerance: 0.001, initial_damping_factor: 0.01, decrement: 1.0, damping: 10000}
)";

// The same case in code: units US (ft, slug, s, lbf).
app::CaseSpec example1InCode() {
  app::CaseSpec spec;
  spec.name = "ex1-in-code";
  spec.units = app::UnitSystem::US;
  element::CableSection section;
  section.area = 0.1;          // ft^2
  section.density = 0.031056;  // slug/ft^3
  section.material =
      std::make_shared<material::LinearElasticCable>(1.0e6, material::Compression::Carry);
  app::CaseLine cable;
  cable.name = "cable";
  for (int k = 0; k <= 8; ++k)
    cable.nodes.push_back(spec.mesh.addNode(Eigen::Vector3d(25.0 * k, 0.0, 0.0)));
  for (int e = 0; e < 8; ++e)
    cable.elements.push_back(spec.mesh.addElement(
        app::ElementSpec::cable({cable.nodes[e], cable.nodes[e + 1]}, section, 0)));
  for (int node : cable.nodes)
    spec.conditions.supports.push_back({node, 1, 0.0, nullptr, 0});               // the x-z plane
  spec.conditions.supports.push_back({cable.nodes.front(), 0, 0.0, nullptr, 0});  // pinned
  spec.conditions.supports.push_back({cable.nodes.front(), 2, 0.0, nullptr, 0});
  spec.conditions.supports.push_back(
      {cable.nodes.back(), 2, 0.0, nullptr, 0});  // a horizontal roller
  spec.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -32.2);
  spec.conditions.nodal_loads.push_back(
      {cable.nodes.back(), Eigen::Vector3d(5.8, 0.0, 0.0), nullptr});
  app::StepSpec relax;
  relax.kind = app::StepSpec::Kind::Relax;
  relax.name = "relax";
  relax.relax.tolerance = 0.001;
  relax.relax.initial_damping_factor = 0.01;
  relax.relax.decrement = 1.0;
  relax.relax.damping = 10000.0;
  spec.steps.push_back(relax);
  spec.lines.push_back(cable);
  return spec;
}

app::SimulationResult run(const app::Case& c) {
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  return simulation.run();
}

TEST(CaseSpecTwin, Example1InCodeIsItsCaseFileToTheBit) {
  const app::Case file = app::readCase(writeCase("ex1-twin.yaml", kExample1));
  const app::Case code = app::buildCase(example1InCode());
  expectSameModel(*file.model, *code.model);
  const model::Model &a = *file.model, &b = *code.model;
  ASSERT_EQ(a.nodalLoads().size(), 1u);
  EXPECT_EQ(a.nodalLoads()[0].node, b.nodalLoads()[0].node);
  EXPECT_EQ(a.nodalLoads()[0].force, b.nodalLoads()[0].force);
  EXPECT_EQ(file.lines, code.lines);

  const app::SimulationResult from_file = run(file), from_code = run(code);
  ASSERT_EQ(from_file.exit_code, app::kSuccess);
  ASSERT_EQ(from_code.exit_code, app::kSuccess);
  const model::State &s = from_file.states.back(), &t = from_code.states.back();
  EXPECT_EQ(s.displacement, t.displacement);             // to the bit
  EXPECT_GT(s.displacement.cwiseAbs().maxCoeff(), 1.0);  // it did sag (ft)
}

TEST(CaseSpecTwin, WhatTheSpecificationsGetWrongIsRefusedWithItsReason) {
  app::CaseSpec spec = example1InCode();
  spec.conditions.nodal_loads.push_back({42, Eigen::Vector3d::UnitX(), nullptr});
  expectRefused(spec, "a load: node 42 is not in the mesh (9 nodes, 0-based)");
  spec = example1InCode();
  spec.steps.clear();
  expectRefused(spec, "no steps");
  spec = example1InCode();
  for (int n = 0; n < spec.mesh.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) spec.conditions.supports.push_back({n, k, 0.0, nullptr, 0});
  expectRefused(spec, "every dof is fixed");
  spec = example1InCode();  // a liquid in no membranes, one in an element not in the mesh
  spec.enclosed_fluids.push_back({{}, {1000.0, 0.0, 0.0, 0.0}, 0, "water in nothing"});
  spec.enclosed_fluids.push_back({{99}, {1000.0, 0.0, 0.0, 0.0}, 0, "water in 99"});
  expectRefused(spec, "ex1-in-code: water in nothing.on: names no membranes");
  expectRefused(spec,
                "ex1-in-code: water in 99.on: element 99 is not in the mesh (8 elements, 0-based)");
}

}  // namespace
}  // namespace flexmoor::test
