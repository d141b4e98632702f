// End tensions of cable elements: the force on the end point, from each element's nodal force
// balance (Assembler::elementResults), against the statics of the catenary.
//
// The catenary's tension does not depend on the cable's law: with H the horizontal force, V the
// vertical reaction and w the weight per unstretched length, T(s) = sqrt(H^2 + (V - w s)^2) at
// unstretched arc length s from the pin (tests/support/elastic_catenary.hpp). At the supports
// T = sqrt(H^2 + V^2), V = w L0 / 2 by symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/shape/gauss_legendre.hpp"
#include "libstruct/solve/newmark.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"
#include "tests/support/cable_models.hpp"

namespace flexmoor::test {
namespace {

struct EndTensionErrors {
  double pin = 0.0;            // relative error of the end tension at the pin
  double roller = 0.0;         // at the roller
  double joints = 0.0;         // largest relative error at the element joints, both sides
  double strain_pin = 0.0;     // the element's own axial force from the strain at xi = -1
  double point_tension = 0.0;  // largest relative error of the Gauss-point tensions
};

// A cable element's axial force from its strain at xi.
template <int N>
double strainTension(const element::Element& e, const element::ElementContext& c, double xi) {
  return dynamic_cast<const element::CableElement<N>&>(e).axialForceAt(c, xi);
}

// Example 1's cable (L0 = 200 ft, EA = 1e5 lbf, w = 0.1 lbf/ft, H = 5.8 lbf: EA / T ~ 1e4), hung by
// viscous relaxation and then Newton to a residual of 1e-12.
EndTensionErrors hangAndMeasure(int elements, int nodes_per_element) {
  const SuspendedCableInputs inputs;
  const CatenaryInputs cat = inputs.catenary();
  const SuspendedCable cable =
      makeSuspendedCable(inputs, elements, nodes_per_element, material::Compression::Carry);
  const model::Assembler assembler(*cable.model);
  model::State state = cable.model->initialState();
  solve::relax(assembler, state, exampleOneRelaxation());
  solve::StaticOptions newton;
  newton.convergence.residual_tolerance = 1e-12;
  newton.convergence.use_displacement = false;
  solve::solveStatic(assembler, state, newton);

  const double H = cat.horizontal_force, V = cat.verticalReaction(), w = cat.weight;
  const auto exact = [&](double s) { return std::hypot(H, V - w * s); };
  const double L0 = cat.unstretched_length, element_length = L0 / elements;
  const std::vector<element::ElementResult> results = assembler.elementResults(state);
  EndTensionErrors e;
  const double T_end = exact(0.0);
  e.pin = std::abs(results.front().end_tension[0] / T_end - 1.0);
  e.roller = std::abs(results.back().end_tension[1] / exact(L0) - 1.0);
  for (int k = 0; k + 1 < elements; ++k) {
    const double T = exact((k + 1) * element_length);
    e.joints = std::max({e.joints, std::abs(results[k].end_tension[1] / T - 1.0),
                         std::abs(results[k + 1].end_tension[0] / T - 1.0)});
  }
  const model::Model& m = *cable.model;
  const element::ElementContext first{m.reference(), state, 0};
  const double strain_end = nodes_per_element == 2   ? strainTension<2>(m.element(0), first, -1.0)
                            : nodes_per_element == 3 ? strainTension<3>(m.element(0), first, -1.0)
                                                     : strainTension<4>(m.element(0), first, -1.0);
  e.strain_pin = std::abs(strain_end / T_end - 1);
  // Gauss points: T at the point's unstretched arc length (reference elements are straight and
  // uniformly parametrised, so s = (k + (1 + xi) / 2) h0).
  const auto& rule = shape::gaussLegendre(nodes_per_element);
  for (int k = 0; k < elements; ++k)
    for (int q = 0; q < rule.size(); ++q) {
      const double s = (k + 0.5 * (1.0 + rule.points[q])) * element_length;
      e.point_tension =
          std::max(e.point_tension, std::abs(results[k].point_tension[q] / exact(s) - 1.0));
    }
  std::cout << "[ " << elements << " x L" << nodes_per_element << " ] end tension error: pin "
            << e.pin << ", roller " << e.roller << ", joints " << e.joints
            << "; from the strain at the pin end: " << e.strain_pin
            << "; Gauss-point tensions: " << e.point_tension << "\n";
  return e;
}

// The end forces are what the nodal equilibrium leaves, so their error is that of the residual,
// whose test cannot go below the round-off floor (Residual::floor): eps rms|x| max K_ii sqrt(n)
// / |F| = 2.2e-16 x 100 ft x 1.6e4 lbf/ft x 8 / 11.6 lbf = 2.5e-10 here. Tolerance 3e-10 at every
// end, just above that floor (the measured errors below are under it).

// 16 quadratic elements. The axial force from the strain at xi = -1, taken as the end tension,
// is 1.16 (116%) off at the pin, with the Gauss-point tensions off by up to 2.9 times the true
// one, while the shape is right to 4e-4 and the reactions to the residual. By the balance:
// measured 2.3e-12 at the pin, 2.8e-11 at the roller, 4.9e-11 at the joints (the nodal forces of
// a one-dimensional element are exact where its interior equations hold).
TEST(EndTension, QuadraticCatenaryEndsFromTheNodalForceBalance) {
  const EndTensionErrors e = hangAndMeasure(16, 3);
  EXPECT_LT(e.pin, 3e-10);
  EXPECT_LT(e.roller, 3e-10);
  EXPECT_LT(e.joints, 3e-10);
}

// 16 cubic elements. Before: 4.8e-2 at the pin (Gauss points 3.2e-2). Now: 5.8e-13 at the pin,
// 5.5e-12 at the roller, 1.1e-10 at the joints.
TEST(EndTension, CubicCatenaryEndsFromTheNodalForceBalance) {
  const EndTensionErrors e = hangAndMeasure(16, 4);
  EXPECT_LT(e.pin, 3e-10);
  EXPECT_LT(e.roller, 3e-10);
  EXPECT_LT(e.joints, 3e-10);
}

// A cable falling freely under gravity, unsupported and unstressed: every end force is zero,
// since the element's inertia M u'' balances its weight share exactly (consistent mass and body
// load share the shape functions, u'' = g). Without the inertia term the ends would report their
// share of the weight (w L / 6 on a quadratic element's ends). Tolerance: 1e-12 of that share.
TEST(EndTension, FreelyFallingCableHasNoEndTension) {
  model::Model m;
  const int a = m.addNode(Eigen::Vector3d::Zero());
  const int b = m.addNode(Eigen::Vector3d(10.0, 0.0, 0.0));
  addStraightCable(m, a, b, 4, 3,
                   linearElasticSection(2.0e11, 1.0e-4, 7850.0, material::Compression::Carry));
  m.setGravity(Eigen::Vector3d(0.0, 0.0, -9.81));
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State state = m.initialState();
  solve::DynamicOptions o;
  o.load_factor = 1.0;
  o.schedule = {{0.01, 10}};
  solve::integrate(assembler, state, o);
  EXPECT_NEAR(state.displacement(2, b), -0.5 * 9.81 * 0.1 * 0.1, 1e-12);  // z = -g t^2 / 2
  const double share = 7850.0 * 1.0e-4 * 2.5 * 9.81 / 6.0;
  for (const element::ElementResult& r : assembler.elementResults(state)) {
    EXPECT_NEAR(r.end_tension[0], 0.0, 1e-12 * share);
    EXPECT_NEAR(r.end_tension[1], 0.0, 1e-12 * share);
  }
}

}  // namespace
}  // namespace flexmoor::test
