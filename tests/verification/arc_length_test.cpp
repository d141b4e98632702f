// Arc-length continuation through a limit point: the shallow two-bar (von Mises) truss under a
// load at its apex snaps through. Its load-deflection curve, in closed form, rises to a limit
// load, falls through zero where the bars lie flat, goes negative, and rises again once the truss
// hangs inverted. Asked for 1.5 times the limit load, the arc-length solver must follow the
// falling (unstable) branch and land on the inverted equilibrium.
//
// Closed form (docs/theory.md#cable-laws, Eq. 2.53, S = E (lambda^2 - 1) / 2): half span b, rise h, bar
// length L0 = sqrt(b^2 + h^2). With the apex lowered by w, a bar is l = sqrt(b^2 + (h - w)^2)
// long, stretched lambda = l / L0, and carries N = S lambda A0; vertical equilibrium of the apex
// gives P(w) = -2 N (h - w) / l (positive downwards). Bars carry compression (Compression::Carry).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/scalar_root.hpp"

namespace flexmoor {
namespace {

constexpr double kB = 1.0, kH = 0.1, kE = 1.0e4, kArea = 1.0;

double apexLoad(double w) {
  const double L0 = std::hypot(kB, kH), l = std::hypot(kB, kH - w), lambda = l / L0;
  const double N = kE * (lambda * lambda - 1.0) / 2.0 * lambda * kArea;
  return -2.0 * N * (kH - w) / l;
}

// The limit load: the largest P on the rising branch (golden-section search on [0, h]).
double limitLoad() {
  double lo = 0.0, hi = kH;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    (apexLoad(a) > apexLoad(b) ? hi : lo) = apexLoad(a) > apexLoad(b) ? b : a;
  }
  return apexLoad(0.5 * (lo + hi));
}

TEST(ArcLength, FollowsTheSnapThroughOfAShallowTrussToTheInvertedBranch) {
  const double p_limit = limitLoad();
  model::Model m;
  const int left = m.addNode({0.0, 0.0, 0.0});
  const int apex = m.addNode({kB, 0.0, kH});
  const int right = m.addNode({2.0 * kB, 0.0, 0.0});
  const element::CableSection bar{
      kArea, 0.0, std::make_shared<material::LinearElasticCable>(kE, material::Compression::Carry)};
  m.addElement(element::makeCableElement({left, apex}, bar));
  m.addElement(element::makeCableElement({apex, right}, bar));
  for (int k = 0; k < 3; ++k) {
    m.constrain(left, k);
    m.constrain(right, k);
  }
  m.constrain(apex, 1);
  m.addNodalLoad(apex, Eigen::Vector3d(0.0, 0.0, -p_limit));  // load factor 1 = the limit load
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State state = m.initialState();

  solve::StaticOptions o;
  o.control = solve::LoadControl::ArcLength;
  o.load_factor = 1.5;
  o.increments = 10;
  o.convergence.displacement_tolerance = 1e-12;
  const solve::StaticReport report = solve::solveStatic(assembler, state, o);

  // On the inverted branch: P(w) = 1.5 P_limit with w beyond 2 h.
  const double w_exact =
      test::findRoot([&](double w) { return apexLoad(w) - 1.5 * p_limit; }, 2.0 * kH, 10.0 * kH);
  const double w = -state.displacement(2, apex);
  EXPECT_NEAR(w, w_exact, 1e-8 * kH);
  EXPECT_NEAR(state.displacement(0, apex), 0.0, 1e-10);
  // The path rose to the limit point (load factor 1), then went down the unstable branch through
  // zero load before rising again.
  const auto& incs = report.increments;
  const auto by_load = [](const auto& a, const auto& b) { return a.load_factor < b.load_factor; };
  const auto peak = std::max_element(incs.begin(), incs.end() - 1, by_load);
  const auto lowest = std::min_element(peak, incs.end(), by_load);
  EXPECT_GT(peak->load_factor, 0.9);
  EXPECT_LE(peak->load_factor, 1.0 + 1e-9);
  EXPECT_LT(lowest->load_factor, 0.0);
  RecordProperty("increments", static_cast<int>(incs.size()));
  EXPECT_DOUBLE_EQ(state.load_factor, 1.5);
}

}  // namespace
}  // namespace flexmoor
