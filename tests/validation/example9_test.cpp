// Example 9, the submerged fluid-filled tube (cases/seed/ex9-submerged-tube.yaml): 6 Q8 + 6 L3,
// the liquid as its pressure plus lumped mass, relaxed to equilibrium, modes 1-6, 10 s under a
// wave train with the self-corrective scheme. The dissertation's figures were not recovered, so
// the checks are independent ones and the behaviour its text reports:
//  - static equilibrium: the anchors' vertical pull equals the buoyancy of the deformed tube
//    minus the liquid's weight, (rho_w - rho_f) g V, minus the membrane's weight, plus the
//    cables' buoyancy minus their weight;
//  - the heave period against a rigid tube on two elastic lines: omega^2 = k_z / M with
//    k_z = sum (EA (3 lambda^2 - 1) / (2 l0)) cos^2 b + (T / l) sin^2 b (the axial stiffness of
//    S = E (lambda^2 - 1) / 2 and the geometric stiffness, b the line's angle from vertical) and
//    M the membrane and liquid mass (no added mass of the sea: no radiation, as in the
//    dissertation);
//  - the six periods below the 5 s wave period; nodes 4 and 10 rolling 180 degrees out of phase.
//    (Nodes 1 and 7 sway out of phase in this reconstruction, in phase in the dissertation's: the
//    lost mooring layout decides it; see the case file. Their correlation is printed.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>
#include <sstream>

#include "apps/case/case_reader.hpp"
#include "apps/output/memory_sink.hpp"
#include "apps/run/simulation.hpp"
#include "libhydro/loads/enclosed_fluid.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;

int nodeAt(const model::Model& m, const Vector3d& x) {
  int best = 0;
  for (int n = 1; n < m.nodeCount(); ++n)
    if ((m.reference().col(n) - x).norm() < (m.reference().col(best) - x).norm()) best = n;
  return best;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0.0, mb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i] / a.size(), mb += b[i] / b.size();
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

class Example9 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    c_ = new app::Case(app::readCase(app::resolveCasePath("ex9-submerged-tube")));
    sink_ = new app::MemorySink;
    std::ostringstream log, diag;
    app::Simulation simulation(*c_, log, diag);
    simulation.addSink(*sink_);
    const std::clock_t start = std::clock();
    result_ = new app::SimulationResult(simulation.run());
    cpu_ = double(std::clock() - start) / CLOCKS_PER_SEC;
    std::cout << "Example 9: " << cpu_ << " s CPU, " << sink_->frames().size() << " records\n";
  }
  static void TearDownTestSuite() {
    delete result_;
    delete sink_;
    delete c_;
  }
  static double summary(const std::string& name) {
    for (const auto& [key, value] : result_->summary)
      if (key == name) return value;
    ADD_FAILURE() << "no summary value " << name;
    return 0.0;
  }
  static app::Case* c_;
  static app::MemorySink* sink_;
  static app::SimulationResult* result_;
  static double cpu_;

  // The data of the case (ft, slug, s, lbf).
  static constexpr double g = 32.174, rho_w = 1.99, rho_f = 0.9 * 1.99;
  static constexpr double rho_m = 1.5228, h = 0.25 / 12.0;
  static constexpr double area_c = 0.06545 / 144.0, ea = 100000.0 * 144.0 * area_c;
  static constexpr double rho_c = 4.6584, d_c = 0.28868 / 12.0;
};

app::Case* Example9::c_ = nullptr;
app::MemorySink* Example9::sink_ = nullptr;
app::SimulationResult* Example9::result_ = nullptr;
double Example9::cpu_ = 0.0;

// Reference: the vertical force balance of the relaxed state, every term computed from the
// deformed geometry (V by libhydro's int z n_z dA, the cables' lengths from their nodes);
// tolerance 1e-4 of the net pull (the relaxation's residual is 2e-11 of the load; the cables'
// buoyancy is taken over their chords, measured below 1e-6 of the pull off their arc).
TEST_F(Example9, AnchorsHoldTheBuoyancyLessTheWeights) {
  ASSERT_EQ(result_->exit_code, app::kSuccess);
  const model::Model& m = *c_->model;
  const app::ResultFrame& eq = sink_->frames().front();
  ASSERT_EQ(eq.step_name, "equilibrium");
  const std::vector<int>& tube = c_->element_sets.at("tube");
  const hydro::Enclosure deformed = hydro::measureEnclosure(m, tube, *eq.state);
  const hydro::Enclosure reference = hydro::measureEnclosure(m, tube, m.initialState());
  double pull = 0.0, cable_net = 0.0;
  for (const char* line : {"mooring_right", "mooring_left"}) {
    const std::vector<int>& nodes = c_->lines.at(line);
    pull -= eq.reactions(2, nodes.back());
    double length = 0.0;
    for (size_t i = 1; i < nodes.size(); ++i) {
      const auto y = [&](int n) -> Vector3d {
        return m.reference().col(n) + eq.state->displacement.col(n);
      };
      length += (y(nodes[i]) - y(nodes[i - 1])).norm();
    }
    const double l0 = (m.reference().col(nodes.back()) - m.reference().col(nodes.front())).norm();
    cable_net += rho_w * g * M_PI * d_c * d_c / 4.0 * length - rho_c * area_c * l0 * g;
  }
  const double expected =
      (rho_w - rho_f) * g * deformed.volume - rho_m * h * reference.area * g + cable_net;
  std::cout << "anchors' pull " << pull << " lbf, buoyancy less weights " << expected
            << " lbf (cables' share " << cable_net << ")\n";
  EXPECT_NEAR(pull / expected, 1.0, 1e-4);
}

// Reference: the rigid heave closed form above on the relaxed state's lines; tolerance 5% (the
// tube ovalises a little under the lines' pull, and mode 2 carries a little of the cables' own
// mass: measured 4.4% slower than the rigid tube).
TEST_F(Example9, HeavePeriodMatchesARigidTubeOnTwoElasticLines) {
  const model::Model& m = *c_->model;
  const app::ResultFrame& eq = sink_->frames().front();
  double kz = 0.0;
  for (const char* line : {"mooring_right", "mooring_left"}) {
    const std::vector<int>& nodes = c_->lines.at(line);
    const Vector3d a = m.reference().col(nodes.front()) + eq.state->displacement.col(nodes.front());
    const Vector3d b = m.reference().col(nodes.back()) + eq.state->displacement.col(nodes.back());
    const double l0 = (m.reference().col(nodes.back()) - m.reference().col(nodes.front())).norm();
    const double l = (a - b).norm(), lambda = l / l0, cos_b = std::abs(a.z() - b.z()) / l;
    const double tension = ea * (lambda * lambda - 1.0) / 2.0 * lambda;  // S A0 lambda
    kz += ea * (3.0 * lambda * lambda - 1.0) / (2.0 * l0) * cos_b * cos_b +
          tension / l * (1.0 - cos_b * cos_b);
  }
  const std::vector<int>& tube = c_->element_sets.at("tube");
  const hydro::Enclosure reference = hydro::measureEnclosure(m, tube, m.initialState());
  const double mass = rho_m * h * reference.area + rho_f * reference.volume;
  const double period = 2.0 * M_PI / std::sqrt(kz / mass);
  std::cout << "heave: rigid closed form " << period << " s, model (mode 2) " << summary("period_2")
            << " s\n";
  EXPECT_NEAR(summary("period_2") / period, 1.0, 0.05);
}

// Reference: the dissertation's text (the longest period below the 5 s wave period; roll of
// nodes 4 and 10 out of phase: correlation of their heave histories over the 10 s measured
// -0.87, expected below -0.5); the cables stay taut (tension above a quarter of the static one:
// measured minimum 93 lbf, 0.57 of the static 163 lbf) and pull harder in the waves than at rest.
TEST_F(Example9, MovesAsTheDissertationReports) {
  for (int k = 1; k <= 6; ++k) EXPECT_LT(summary("period_" + std::to_string(k)), 5.0) << k;
  const model::Model& m = *c_->model;
  const int n1 = nodeAt(m, {0, 0, -40}), n4 = nodeAt(m, {5, 0, -45}), n7 = nodeAt(m, {0, 0, -50}),
            n10 = nodeAt(m, {-5, 0, -45});
  std::vector<double> x1, x7, z4, z10, xc;
  for (const app::ResultFrame& f : sink_->frames()) {
    if (f.step_name != "waves") continue;
    const model::NodalField& u = f.state->displacement;
    x1.push_back(u(0, n1));
    x7.push_back(u(0, n7));
    z4.push_back(u(2, n4));
    z10.push_back(u(2, n10));
    xc.push_back((u(0, n1) + u(0, n4) + u(0, n7) + u(0, n10)) / 4.0);
  }
  ASSERT_EQ(x1.size(), 231u);  // the step's first state and its 230 time steps
  const double sway = correlation(x1, x7), roll = correlation(z4, z10),
               centre = correlation(xc, x1);
  std::cout << "correlations: sway (x1, x7) " << sway << ", roll (z4, z10) " << roll
            << ", centre (xc, x1) " << centre << "\n";
  EXPECT_LT(roll, -0.5);
  double slackest = 1e300;
  for (const app::ResultFrame& f : sink_->frames())
    for (int e = 0; e < m.elementCount(); ++e)
      if (m.element(e).typeName().rfind("cable", 0) == 0)
        slackest = std::min({slackest, f.elements[e].end_tension[0], f.elements[e].end_tension[1]});
  std::cout << "smallest cable end tension " << slackest << " lbf\n";
  EXPECT_GT(slackest, 0.25 * summary("mooring_tension_static"));
  EXPECT_GT(summary("mooring_tension_max"), summary("mooring_tension_static"));
}

// Reference: the case refined (12 Q8 around, 6 L3 a line) through the command. How far the 6 + 6
// model is from converged, bounds just above the measured differences: periods 1-3 (the
// rigid-body and roll modes) within 3.5% (measured +0.9%, +2.8%, 0.0%), node 1's largest sway
// within 3% (+2.2%), node 7's largest heave within 13% (+11%; a small difference of two rises),
// the largest mooring tension within 0.5% (-0.2%).
TEST_F(Example9, RefinedModelStaysClose) {
  std::string text =
      readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/seed/ex9-submerged-tube.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + 1))
      text.replace(at, from.size(), to);
  };
  replace("name: ex9-submerged-tube", "name: ex9-refined");
  replace("divisions: [6, 1]", "divisions: [12, 1]");
  replace("elements: 3, order: 3", "elements: 6, order: 3");
  const std::string json = runCaseText("ex9-refined", text);
  for (const auto& [key, bound] :
       {std::pair{"period_1", 0.035}, std::pair{"period_2", 0.035}, std::pair{"period_3", 0.035},
        std::pair{"node1_x_max", 0.03}, std::pair{"node7_z_max", 0.13},
        std::pair{"mooring_tension_max", 0.005}}) {
    const double refined = summaryValue(json, key), base = summary(key);
    std::cout << key << ": 6 + 6 " << base << ", refined " << refined << " ("
              << 100.0 * (refined / base - 1.0) << "%)\n";
    EXPECT_NEAR(refined / base, 1.0, bound) << key;
  }
}

}  // namespace
}  // namespace flexmoor::test
