// Verification of the Newton statics on a taut cable: a straight cable of span L between pinned
// ends, pretensioned by pulling its right end out by delta (a prescribed displacement of that
// end's x dof), then loaded by a point load P in -z at mid-span.
//
// Exact solution (no weight, so each half is a straight segment, which two-node elements
// represent exactly): by symmetry the mid-span node sits at x = (L + delta) / 2, z = -w. Each half
// has unstretched length L / 2 and current length l = sqrt(((L + delta) / 2)^2 + w^2), so its
// stretch is lambda = 2 l / L and its tension, with flexmoor's law (docs/theory.md, Eq. 2.53,
// S = E (lambda^2 - 1) / 2), T = EA lambda (lambda^2 - 1) / 2. Vertical equilibrium of the loaded
// node: 2 T w / l = P, one scalar equation in w, increasing in w, solved by Brent's method.
// Tolerance: 1e-8 relative on the deflection and the tension (the Newton solve is converged to a
// residual of 1e-12; the rest is round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "libstruct/model/assembler.hpp"
#include "libstruct/model/time_function.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/cable_models.hpp"
#include "tests/support/elastic_catenary.hpp"
#include "tests/support/scalar_root.hpp"

namespace flexmoor::test {
namespace {

struct TautString {
  double span = 100.0;  // L, ft
  double E = 1.0e6;     // psf
  double area = 0.1;    // ft^2, so EA = 1e5 lbf
  double pull = 0.1;    // delta, ft: pretension T0 = EA lambda0 (lambda0^2 - 1) / 2 ~ 100 lbf
  double load = 20.0;   // P, lbf
  double EA() const { return E * area; }
};

struct ClosedForm {
  double deflection;  // w
  double tension;     // T in each half
};

ClosedForm solveClosedForm(const TautString& s) {
  const double half = 0.5 * s.span, chord = 0.5 * (s.span + s.pull);
  const auto tension = [&](double w) {
    return greenStrainTension(std::hypot(chord, w) / half, s.EA());
  };
  const auto imbalance = [&](double w) {
    return 2.0 * tension(w) * w / std::hypot(chord, w) - s.load;
  };
  const double w = findRoot(imbalance, 0.0, s.span);
  return {w, tension(w)};
}

// Convergence tight enough for a 1e-8 comparison.
solve::StaticOptions tightNewton(int increments) {
  solve::StaticOptions o;
  o.increments = increments;
  o.flavour = solve::NewtonFlavour::Full;
  o.convergence.displacement_tolerance = 1e-10;
  o.convergence.residual_tolerance = 1e-12;
  return o;
}

// `elements` two-node elements (an even number, so a node sits at mid-span). The pull is held by
// a constant history, so it is applied in full from the start whatever the load factor; the
// point load scales with the load factor.
struct LoadedString {
  model::Model m;
  std::vector<int> nodes;
  int mid = -1;
};

std::unique_ptr<LoadedString> loadedString(const TautString& s, int elements) {
  auto out = std::make_unique<LoadedString>();
  model::Model& m = out->m;
  const int left = m.addNode(Eigen::Vector3d::Zero());
  const int right = m.addNode(Eigen::Vector3d(s.span, 0.0, 0.0));
  out->nodes =
      addStraightCable(m, left, right, elements, 2,
                       linearElasticSection(s.E, s.area, 0.0, material::Compression::Carry));
  out->mid = out->nodes[out->nodes.size() / 2];
  pin(m, left);
  pin(m, right);
  const auto held =
      std::make_shared<model::TableFunction>(std::vector<double>{0.0}, std::vector<double>{1.0});
  m.constrain(right, 0, s.pull, held);
  m.addNodalLoad(out->mid, Eigen::Vector3d(0.0, 0.0, -s.load));
  m.numberEquations();
  return out;
}

// Pretensions the string: load factor 0 (a straight, unstressed cable has no transverse
// stiffness, and the solver's regularisation carries the unloaded transverse dofs).
model::State pretensioned(const model::Assembler& assembler) {
  model::State state = assembler.model().initialState();
  solve::StaticOptions pretension = tightNewton(1);
  pretension.load_factor = 0.0;
  solve::solveStatic(assembler, state, pretension);
  return state;
}

// The solve pretensions first, then applies the load in `increments` Newton increments.
void expectClosedForm(int elements, int increments) {
  const TautString s;
  const ClosedForm exact = solveClosedForm(s);
  const auto string = loadedString(s, elements);
  const model::Model& m = string->m;
  const std::vector<int>& nodes = string->nodes;
  const int mid = string->mid;
  const model::Assembler assembler(m);
  model::State state = pretensioned(assembler);
  const double pretension_force = assembler.elementResults(state)[0].end_tension[0];
  const solve::StaticReport report = solve::solveStatic(assembler, state, tightNewton(increments));

  const double w = -state.displacement(2, mid);
  const double deflection_error = std::abs(w - exact.deflection) / exact.deflection;
  std::cout << "[ " << elements << " x L2 ] pretension " << pretension_force << " lbf; deflection "
            << w << " ft (closed form " << exact.deflection << ", rel. error " << deflection_error
            << "), tension " << exact.tension << " lbf; iterations per increment:";
  for (const auto& inc : report.increments) std::cout << ' ' << inc.iterations;
  std::cout << "\n";
  ::testing::Test::RecordProperty("deflection_relative_error", std::to_string(deflection_error));

  EXPECT_NEAR(pretension_force, greenStrainTension(1.0 + s.pull / s.span, s.EA()),
              1e-8 * pretension_force);
  EXPECT_LT(deflection_error, 1e-8);
  // Every element carries the tension of its half, and the nodes lie on the two straight halves.
  for (const auto& r : assembler.elementResults(state))
    for (double t : {r.end_tension[0], r.end_tension[1]})
      EXPECT_NEAR(t, exact.tension, 1e-8 * exact.tension);
  const Eigen::Vector3d apex(0.5 * (s.span + s.pull), 0.0, -exact.deflection);
  const Eigen::Vector3d far_end(s.span + s.pull, 0.0, 0.0);
  const int half = static_cast<int>(nodes.size()) / 2;
  for (int k = 0; k < static_cast<int>(nodes.size()); ++k) {
    const double f = static_cast<double>(k) / half;
    const Eigen::Vector3d expected = k <= half
                                         ? Eigen::Vector3d(f * apex)
                                         : Eigen::Vector3d(apex + (f - 1.0) * (far_end - apex));
    const Eigen::Vector3d y = m.reference().col(nodes[k]) + state.displacement.col(nodes[k]);
    EXPECT_LT((y - expected).norm(), 1e-8 * exact.deflection) << "node " << k;
  }
}

TEST(PretensionedCable, PointLoadMatchesClosedForm) {
  expectClosedForm(2, 1);
  expectClosedForm(8, 1);
}

// The same answer reached in four increments (the solution of an elastic structure does not
// depend on the load path).
TEST(PretensionedCable, PointLoadInIncrementsMatchesClosedForm) { expectClosedForm(8, 4); }

// The self-corrective incremental scheme (Eq. 4.20): one solve per increment with the full
// residual, no iterations. Each increment is one Newton step from the last state towards the next
// equilibrium, so it leaves an error of the order of the square of its distance, O(dlambda^2),
// and the next increment corrects it rather than adding to it (the purely incremental scheme of
// Eq. 4.19 would accumulate a first-order error): halving the increment quarters the error. The
// last increment is iterated until it converges (a static step reports only an equilibrium), so
// the error the scheme carried to the end is its first correction, max |du_i| (the iteration
// record's norm times the element size), and the step ends on the closed form.
TEST(PretensionedCable, SelfCorrectiveErrorIsSecondOrderInTheIncrement) {
  const TautString s;
  const ClosedForm exact = solveClosedForm(s);
  const auto string = loadedString(s, 8);
  const model::Assembler assembler(string->m);
  std::vector<double> errors;
  for (int increments : {16, 32, 64}) {
    model::State state = pretensioned(assembler);
    solve::StaticOptions o;
    o.increments = increments;
    o.flavour = solve::NewtonFlavour::SelfCorrective;
    double carried = 0.0;
    solve::SolveLog log;
    log.iteration = [&](const solve::IterationRecord& r) {
      if (r.increment == increments && r.iteration == 2) carried = r.displacement_norm;
    };
    const solve::StaticReport report = solve::solveStatic(assembler, state, o, log);
    ASSERT_EQ(static_cast<int>(report.increments.size()), increments);
    for (int k = 0; k + 1 < increments; ++k) EXPECT_EQ(report.increments[k].iterations, 1);
    EXPECT_GE(report.increments.back().iterations, 2);
    errors.push_back(carried * assembler.elementSize() / exact.deflection);
    EXPECT_NEAR(-state.displacement(2, string->mid), exact.deflection, 1e-8 * exact.deflection);
  }
  std::cout << "[ self-corrective ] carried error at 16, 32, 64 increments: " << errors[0] << ", "
            << errors[1] << ", " << errors[2] << "\n";
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.4);
  EXPECT_NEAR(errors[1] / errors[2], 4.0, 0.4);
  EXPECT_LT(errors[2], 1e-4);
}

}  // namespace
}  // namespace flexmoor::test
