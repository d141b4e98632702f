// A scenario stated in code through its function and the same scenario read from its case file
// give the same model and the same results, to the bit: single_point_moor (singlePointMoor),
// Example 8's case with its values in the case's units written to 17 digits.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "apps/case/build/build_case.hpp"
#include "apps/case/case_reader.hpp"
#include "apps/case/scenarios/single_point_moor.hpp"
#include "apps/output/memory_sink.hpp"
#include "apps/run/simulation.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::test {
namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A run and every record it makes.
struct Recorded {
  app::SimulationResult result;
  app::MemorySink records;
};

void run(const app::Case& c, Recorded& out) {
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  simulation.addSink(out.records);
  out.result = simulation.run();
}

void expectSameRun(const app::Case& file, const app::Case& code) {
  ASSERT_EQ(file.model->reference(), code.model->reference());
  ASSERT_EQ(file.model->elementCount(), code.model->elementCount());
  EXPECT_EQ(file.lines, code.lines);
  Recorded a, b;
  run(file, a);
  run(code, b);
  ASSERT_EQ(b.result.exit_code, app::kSuccess);
  ASSERT_EQ(a.records.frames().size(), b.records.frames().size());
  ASSERT_GT(b.records.frames().size(), 2u);
  for (size_t i = 0; i < a.records.frames().size(); ++i) {
    const model::State &s = *a.records.frames()[i].state, &t = *b.records.frames()[i].state;
    ASSERT_EQ(s.time, t.time) << i;
    ASSERT_EQ(s.displacement, t.displacement) << "record " << i << " at t = " << s.time;
    ASSERT_EQ(s.velocity, t.velocity) << i;
  }
  ASSERT_EQ(a.result.summary.size(), b.result.summary.size());
  for (size_t i = 0; i < a.result.summary.size(); ++i) {
    EXPECT_EQ(a.result.summary[i].first, b.result.summary[i].first);
    EXPECT_EQ(a.result.summary[i].second, b.result.summary[i].second) << a.result.summary[i].first;
  }
  ASSERT_TRUE(code.figure.has_value());
  EXPECT_EQ(file.figure->series, code.figure->series);
}

// Example 8 in US units (ft, slug, s, lbf): the line 71.56 in, EA 4.8 lbf, 11.443e-3 lbf/ft in
// air, 0.163 in across; the buoy held at (50 in, 50 in), 2 in across, 0.025 lbf in air and
// -0.121 lbf in water, Cd 0.5; released for 200 steps of 0.005 s.
app::SinglePointMoorSpec example8() {
  app::SinglePointMoorSpec spec;
  spec.units = app::UnitSystem::US;
  const double g = 32.174, rho = 1.94364, depth = 80.0 / 12.0;
  spec.water = {rho, depth, g};
  spec.anchor = Eigen::Vector3d(0.0, 0.0, -depth);
  spec.length = 71.56 / 12.0;
  spec.ea = 4.8;
  spec.weight_in_air = 11.443e-3;
  spec.hydro.coefficients = {
      0.163 / 12.0, 1.2, 0.02, 1.0, 0.0, hydro::MorisonCoefficients::TangentialDragArea::Diameter};
  spec.held_x = 50.0 / 12.0;
  spec.held_z = 50.0 / 12.0;
  const double d = 2.0 / 12.0;
  spec.buoy = hydro::PointBody{(0.025 + 0.121) / (rho * g), 0.5 * M_PI * d * d / 4.0, 0.5, 0.0};
  spec.buoy_mass = 0.025 / g;
  return spec;
}

std::string example8File(const app::SinglePointMoorSpec& s) {
  const double d = s.hydro.coefficients.diameter;
  return "units: US\nscenario: single_point_moor\n"
         "water: {density: " +
         number(s.water.density) + ", depth: " + number(s.water.depth) +
         "}\ngravity: " + number(s.water.gravity) + "\ncable: {length: " + number(s.length) +
         ", EA: " + number(s.ea) + ", weight_in_air: " + number(s.weight_in_air) +
         ", diameter: " + number(d) +
         ", elements: 4, order: 3, Cn: 1.2, Ct: 0.02, Ca: 1.0, tangential_drag_area: diameter}\n"
         "buoy: {held_at: [" +
         number(s.held_x) + ", " + number(s.held_z) + "], diameter: " + number(2.0 / 12.0) +
         ", weight_in_air: 0.025, weight_in_water: -0.121, Cd: 0.5, Ca: 0.5}\n"
         "dynamic: {dt: 0.005, steps: 200, newton: modified, stiffness_update: 2, tolerance: "
         "1e-3}\n";
}

TEST(ScenarioSpecTwin, SinglePointMoorInCodeIsItsCaseFileToTheBit) {
  const app::SinglePointMoorSpec spec = example8();
  const app::Case file = app::readCase(writeCase("ex8-twin.yaml", example8File(spec)));
  app::StepSpec release = app::singlePointMoorRelease(8);  // the buoy: the cable's 9th node
  release.dynamic.schedule = {{0.005, 200}};
  release.dynamic.flavour = solve::NewtonFlavour::Modified;
  release.dynamic.stiffness_update = 2;
  release.dynamic.convergence.displacement_tolerance = 1e-3;
  const app::Case code =
      app::buildCase(app::singlePointMoor(spec, {app::singlePointMoorHold(spec), release}));
  EXPECT_EQ(code.lines.at("cable").back(), 8);
  expectSameRun(file, code);
}

}  // namespace
}  // namespace flexmoor::test
