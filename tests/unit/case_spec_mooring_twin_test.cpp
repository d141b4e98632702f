// A mooring case stated in code (CaseSpec with its ocean, catenary starts and platform motion,
// buildCase) and the same case read from its case file build the same model and give the same
// results, to the bit: the OC4-DeepCwind semi-submersible's three chains, started on their
// catenaries with seabed contact, Morison loads per unstretched length and axial damping, the
// fairleads carried by the platform surging 2 m at 10 s (cases/ocean/oc4-semi-surge.yaml, a
// spread_mooring scenario, its surge shortened to 20 s and its summary window to t >= 10 s).
// And what the ocean and the catenary starts get wrong is refused with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "apps/case/build/build_case.hpp"
#include "apps/case/case_reader.hpp"
#include "apps/case/scenarios/spread_mooring.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/model/rigid_point_motion.hpp"
#include "libstruct/model/time_function.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/twin_runs.hpp"

namespace flexmoor::test {
namespace {

constexpr int kSurgeSteps = 200;  // of 0.1 s: the ramp's 10 s and one full period

// The shipped case, its surge shortened and its summary's window moved into it.
std::string oc4CaseFile() {
  std::string text = shippedCaseText("ocean/oc4-semi-surge");
  const auto replace = [&text](const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  };
  replace("steps: 6000", "steps: " + std::to_string(kSurgeSteps));
  replace("from: 100 s", "from: 10 s");
  return writeCase("oc4-twin.yaml", text);
}

// The same case in code, SI units, as a program states it: the chain's section from its
// diameter, mass per length and EA; each line's reference laid straight along the bed from its
// anchor towards its fairlead, 12 cubic elements; the fairleads points of the surging platform.
app::CaseSpec oc4InCode() {
  const double g = 9.80665, depth = 200.0, length = 835.35, d = 0.0766;
  const double area = M_PI * d * d / 4.0;
  app::CaseSpec spec;
  spec.name = "oc4-in-code";
  spec.units = app::UnitSystem::SI;
  element::CableSection chain;
  chain.area = area;
  chain.density = 113.35 / area;  // kg/m over the area
  chain.material = std::make_shared<material::EngineeringStrainCable>(
      7.536e8 / area, material::Compression::TensionOnly);
  chain.axial_damping = 3.052e6;  // BA, N s

  spec.ocean = app::OceanSpec::inWater({1025.0, depth, g});
  spec.ocean.has_contact = true;  // MoorDyn's bed: 3e6 Pa/m, 3e5 Pa s/m, no friction
  app::MorisonSpec morison;
  morison.hydro.coefficients = {
      d, 2.0, 0.4, 0.8, 0.25, hydro::MorisonCoefficients::TangentialDragArea::Perimeter};
  morison.hydro.per_length = model::LengthMeasure::Reference;

  model::RigidBodyMotion::Dofs surge;  // 2 m at 10 s, ramped in over its period
  surge[0] = std::make_shared<model::RampedFunction>(
      std::make_shared<model::SineFunction>(0.0, 2.0, 10.0, 0.0), 0.0, 10.0);
  const auto platform = std::make_shared<model::RigidBodyMotion>(surge);
  spec.rigid_motions["platform"] = platform;

  const Eigen::Vector3d anchors[3] = {
      {418.8, 725.383, -200.0}, {-837.6, 0.0, -200.0}, {418.8, -725.383, -200.0}};
  const Eigen::Vector3d fairleads[3] = {
      {20.434, 35.393, -14.0}, {-40.868, 0.0, -14.0}, {20.434, -35.393, -14.0}};
  for (int k = 0; k < 3; ++k) {
    app::CaseLine line;
    line.name = "line_" + std::to_string(k + 1);
    line.anchor = app::CaseLine::Anchor::Start;
    const Eigen::Vector3d &anchor = anchors[k], &fairlead = fairleads[k];
    const Eigen::Vector3d along =
        Eigen::Vector3d(fairlead.x() - anchor.x(), fairlead.y() - anchor.y(), 0.0).normalized();
    const Eigen::Vector3d end = anchor + length * along;
    for (int i = 0; i <= 24; ++i) {
      const double s = i / 24.0;
      line.nodes.push_back(spec.mesh.addNode((1.0 - s) * anchor + s * end));
    }
    for (int e = 0; e < 12; ++e) {
      const std::vector<int> nodes(line.nodes.begin() + 2 * e, line.nodes.begin() + 2 * e + 3);
      line.elements.push_back(spec.mesh.addElement(app::ElementSpec::cable(nodes, chain, 0)));
    }
    morison.elements.insert(morison.elements.end(), line.elements.begin(), line.elements.end());
    for (int c = 0; c < 3; ++c)
      spec.conditions.supports.push_back({line.nodes.front(), c, 0.0, nullptr, 0});
    for (int c = 0; c < 3; ++c)  // the fairlead's rest position plus the platform's motion
      spec.conditions.supports.push_back(
          {line.nodes.back(), c, 1.0,
           std::make_shared<model::RigidPointMotion>(platform, fairlead, c, fairlead(c) - end(c)),
           0});
    spec.catenary_starts.push_back({{{line.nodes, chain, d}}, 0.0, 0.1, 0, line.name});
    spec.lines.push_back(line);
  }
  spec.ocean.morison.push_back(morison);
  spec.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -g);

  app::StepSpec statics;  // Newton from the catenaries, the load factor already 1
  statics.kind = app::StepSpec::Kind::Static;
  statics.name = "equilibrium";
  app::StepSpec dynamic;
  dynamic.kind = app::StepSpec::Kind::Dynamic;
  dynamic.name = "surge";
  dynamic.dynamic.schedule = {{0.1, kSurgeSteps}};
  dynamic.dynamic.hht_alpha = -0.1;
  dynamic.dynamic.convergence.use_residual = false;  // criterion: displacement
  dynamic.dynamic.convergence.displacement_tolerance = 1e-5;
  spec.steps = {statics, dynamic};

  for (int k = 0; k < 3; ++k)
    for (const auto reduction :
         {app::SummarySpec::Reduction::Min, app::SummarySpec::Reduction::Max}) {
      app::SummarySpec s;
      s.name = std::string(reduction == app::SummarySpec::Reduction::Min ? "tension_min_"
                                                                         : "tension_max_") +
               std::to_string(k + 1);
      s.quantity = app::SummarySpec::Quantity::EndTension;
      s.element = spec.lines[k].elements.back();
      s.end = 1;  // the fairlead
      s.reduction = reduction;
      s.from = 10.0;
      s.unit = "N";
      spec.summary.push_back(s);
    }
  app::SummarySpec cpu;
  cpu.name = "cpu_seconds";
  cpu.quantity = app::SummarySpec::Quantity::CpuSeconds;
  cpu.unit = "s";
  spec.summary.push_back(cpu);
  return spec;
}

TEST(CaseSpecMooringTwin, Oc4InCodeIsItsCaseFileToTheBit) {
  const app::Case file = app::readCase(oc4CaseFile());
  const app::Case code = app::buildCase(oc4InCode());
  expectSameModel(*file.model, *code.model);
  ASSERT_TRUE(code.seabed_contact.has_value());
  EXPECT_EQ(file.seabed_contact, code.seabed_contact);
  EXPECT_EQ(file.model->startState().load_factor, code.model->startState().load_factor);
  EXPECT_EQ(file.lines, code.lines);
  ASSERT_EQ(code.rigid_motions.count("platform"), 1u);

  RecordedRun from_file, from_code;
  runRecorded(file, from_file);
  runRecorded(code, from_code);
  expectSameRecords(from_file, from_code);
  expectSameSummary(from_file, from_code);
  const std::vector<app::ResultFrame>& records = from_code.records.frames();
  ASSERT_EQ(records.size(), kSurgeSteps + 2u);  // the equilibrium, then every time step
  const model::State& last = *records.back().state;
  EXPECT_DOUBLE_EQ(last.time, 0.1 * kSurgeSteps);
  // The fairlead surged: line 2's (on the x axis) is 2 sin(2 pi t / 10) m from its rest at 20 s.
  const int fairlead = code.lines.at("line_2").back();
  const double rest = -40.868 - code.model->reference()(0, fairlead);
  EXPECT_NEAR(last.displacement(0, fairlead) - rest, 2.0 * std::sin(2.0 * M_PI * 2.0), 1e-9);
  EXPECT_EQ(from_code.result.summary.size(), 7u);
}

// The same case through the scenario's function: OC4's chain as a line type of its diameter,
// mass per length and EA, the three lines from their anchors to their fairlead points, the
// platform's surge; the case file's steps.
app::CaseSpec oc4ThroughTheScenario() {
  app::LineHydroSpec hydro;
  hydro.coefficients = {0.0, 2.0,  0.4,
                        0.8, 0.25, hydro::MorisonCoefficients::TangentialDragArea::Perimeter};
  hydro.per_length = model::LengthMeasure::Reference;
  app::LineType chain = app::LineType::of(0.0766, 113.35, 7.536e8, hydro);
  chain.section.axial_damping = 3.052e6;
  app::SpreadMooringSpec spec;
  spec.water = {1025.0, 200.0, 9.80665};
  spec.line_types["chain"] = chain;
  const Eigen::Vector3d anchors[3] = {
      {418.8, 725.383, -200.0}, {-837.6, 0.0, -200.0}, {418.8, -725.383, -200.0}};
  const Eigen::Vector3d fairleads[3] = {
      {20.434, 35.393, -14.0}, {-40.868, 0.0, -14.0}, {20.434, -35.393, -14.0}};
  for (int k = 0; k < 3; ++k) {
    app::MooringLine line;
    line.anchor = anchors[k];
    line.fairlead = fairleads[k];
    line.segments = {{"chain", 835.35, 12, 3}};
    spec.lines.push_back(line);
  }
  model::RigidBodyMotion::Dofs surge;
  surge[0] = std::make_shared<model::RampedFunction>(
      std::make_shared<model::SineFunction>(0.0, 2.0, 10.0, 0.0), 0.0, 10.0);
  spec.platform =
      app::PlatformSpec{Eigen::Vector3d::Zero(), std::make_shared<model::RigidBodyMotion>(surge)};
  return app::spreadMooring(spec, oc4InCode().steps);
}

TEST(CaseSpecMooringTwin, TheScenarioInCodeIsItsCaseFileToTheBit) {
  const app::Case file = app::readCase(oc4CaseFile());
  const app::Case code = app::buildCase(oc4ThroughTheScenario());
  expectSameModel(*file.model, *code.model);
  EXPECT_EQ(file.lines, code.lines);
  RecordedRun from_file, from_code;
  runRecorded(file, from_file);
  runRecorded(code, from_code);
  expectSameRecords(from_file, from_code);
  ASSERT_EQ(from_code.records.frames().size(), kSurgeSteps + 2u);
  // The scenario's default summary: line 2's fairlead tension over the surge, as the file's own
  // tension_max_2 over t >= 10 s is at most.
  std::map<std::string, double> summary(from_code.result.summary.begin(),
                                        from_code.result.summary.end());
  std::map<std::string, double> own(from_file.result.summary.begin(),
                                    from_file.result.summary.end());
  ASSERT_EQ(summary.count("fairlead_tension_max_2"), 1u);
  EXPECT_GE(summary.at("fairlead_tension_max_2"), own.at("tension_max_2"));
  EXPECT_EQ(summary.count("length_on_seabed_static_3"), 1u);
  EXPECT_EQ(from_code.result.summary.size(), 3u * (7u + 4u));
}

TEST(CaseSpecMooringTwin, WhatTheOceanAndTheStartsGetWrongIsRefusedWithItsReason) {
  app::CaseSpec spec = oc4InCode();
  spec.ocean.morison.front().elements.push_back(36);
  expectRefused(spec, "Morison loads: element 36 is not in the mesh (36 elements, 0-based)");
  spec = oc4InCode();
  spec.ocean.has_water = false;
  expectRefused(spec, "the ocean's loads need its water");
  spec = oc4InCode();
  spec.catenary_starts[1].parts.front().nodes.back() = 99;
  expectRefused(spec, "line_2: node 99 is not in the mesh (75 nodes, 0-based)");
  spec = oc4InCode();  // a fairlead moved 2 km: the 835 m line cannot reach it
  for (app::SupportSpec& s : spec.conditions.supports)
    if (s.node == spec.lines[0].nodes.back() && s.component == 0) {
      s.history = nullptr;
      s.displacement = 2000.0;
    }
  expectRefused(spec, "line_1: catenary: the line is too short for its span");
  spec = oc4InCode();
  spec.conditions.gravity.reset();
  expectRefused(spec, "line_1: a catenary needs gravity along -z");
}

// buildCase runs the checks a case file's built model gets (check/model_checks.hpp), so that a
// case stated in code is refused for what its file would be, with every reason.
TEST(CaseSpecMooringTwin, TheCaseFilesChecksRefuseWhatTheyRefuseThere) {
  app::CaseSpec spec = oc4InCode();  // line 1 held at neither end: the bed holds it in z only
  spec.conditions.supports.erase(spec.conditions.supports.begin(),
                                 spec.conditions.supports.begin() + 6);
  expectRefused(spec,
                "oc4-in-code: line 'line_1' (25 nodes) is free to move in x, y as a rigid "
                "body: nothing holds it there");
  spec = oc4InCode();  // a spring with Morison loads, a node below the bed
  const int spring = spec.mesh.addElement(
      app::ElementSpec::spring(spec.lines[0].nodes[3], spec.lines[1].nodes[3], 1e3, -1.0,
                               material::Compression::TensionOnly, 0.0));
  spec.ocean.morison.front().elements.push_back(spring);
  spec.mesh.reference(2, spec.lines[2].nodes[1]) = -250.0;
  try {
    app::buildCase(spec);
    ADD_FAILURE() << "not refused";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("oc4-in-code: element 37 (spring of mesh.elements[36]): Morison loads act "
                        "on lines only (got Morison loads on a spring, expected Morison loads on "
                        "cables only)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("oc4-in-code: node 52: below the seabed (got z = -250 m, expected z >= "
                        "-200 m"),
              std::string::npos)
        << what;
  }
}

// An adaptive step without dt_max is bounded as a case file's is: a tenth of the shortest period
// that drives the model, the platform's 10 s.
TEST(CaseSpecMooringTwin, AnAdaptiveStepIsBoundedAsItsCaseFilesIs) {
  app::CaseSpec spec = oc4InCode();
  solve::AdaptiveSteps adaptive;
  adaptive.duration = 20.0;
  spec.steps[1].dynamic.schedule.clear();
  spec.steps[1].dynamic.adaptive = adaptive;
  const app::Case code = app::buildCase(spec);
  ASSERT_TRUE(code.steps[1].adaptive());
  EXPECT_EQ(code.steps[1].dynamic.adaptive->dt_max, 1.0);
}

}  // namespace
}  // namespace flexmoor::test
