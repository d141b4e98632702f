// A body on the bed (SeabedNodeLoad): a steel sphere (D = 0.5 m, 7850 kg/m^3) as a point mass with
// its water load (BodyNodeLoad) on a flat bed 30 m down, x and y held, solved statically from 1 mm
// inside the bed. It delivers its submerged weight W = (rho_s - rho_w) g V to the bed (the
// contact force at the solution) at the penetration W / (k_b A) of its lowest point, A = pi D^2/4.
// Tolerance 1e-10 relative (Newton's increment test is 1e-12); and the load's analytic
// derivatives against central differences (model::numericalJacobians) in contact, 1e-7 relative.
#include <gtest/gtest.h>

#include <cmath>

#include "libhydro/loads/body_node_load.hpp"
#include "libhydro/seabed/seabed_node_load.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

constexpr double kDepth = 30.0, kDiameter = 0.5, kSteel = 7850.0;
const double kPi = std::acos(-1.0);
const double kVolume = kPi * kDiameter * kDiameter * kDiameter / 6.0;
const double kArea = kPi * kDiameter * kDiameter / 4.0;

TEST(BodyOnSeabed, DeliversItsSubmergedWeightAtThePenetration) {
  model::Model m;
  const int node = m.addNode(Eigen::Vector3d(0.0, 0.0, -kDepth + 0.5 * kDiameter - 1e-3));
  m.addElement(std::make_unique<element::PointMassElement>(node, kSteel * kVolume));
  m.addNodeLoad(std::make_shared<hydro::BodyNodeLoad>(
      node, hydro::PointBody::sphere(kDiameter, 0.5), stillWater(kDepth)));
  const hydro::SeabedProperties bed;
  const auto contact = std::make_shared<hydro::SeabedNodeLoad>(
      node, hydro::Bathymetry::flat(kDepth), bed, kArea, 0.5 * kDiameter);
  m.addNodeLoad(contact);
  m.setGravity(Eigen::Vector3d(0.0, 0.0, -kStandardGravity));
  m.constrain(node, 0);
  m.constrain(node, 1);
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State s = m.initialState();
  solve::StaticOptions options;
  options.convergence.displacement_tolerance = 1e-12;
  options.convergence.use_residual = false;
  solve::solveStatic(assembler, s, options);

  const double weight = (kSteel - kSeaWaterDensity) * kStandardGravity * kVolume;
  model::LoadPoint p;
  p.position = m.reference().col(node) + s.displacement.col(node);
  p.node = node;
  EXPECT_NEAR(contact->evaluate(p, false).force.z() / weight, 1.0, 1e-10);
  const double penetration = -kDepth - (p.position.z() - 0.5 * kDiameter);
  EXPECT_NEAR(penetration / (weight / (bed.stiffness * kArea)), 1.0, 1e-10);
}

TEST(BodyOnSeabed, ContactDerivativesMatchCentralDifferences) {
  hydro::SeabedProperties bed;
  bed.friction = 0.6;
  const hydro::SeabedNodeLoad contact(0, hydro::Bathymetry::plane(-kDepth, 0.1, -0.05), bed, kArea,
                                      0.5 * kDiameter);
  model::LoadPoint p;
  p.position = Eigen::Vector3d(2.0, 1.0, -kDepth + 0.15 + 0.5 * kDiameter - 0.01);  // 1 cm in
  p.velocity = Eigen::Vector3d(0.03, -0.02, -0.01);
  const model::PointForce analytic = contact.evaluate(p, true);
  ASSERT_GT(analytic.force.norm(), 0.0);  // in contact
  const model::PointForce fd = model::numericalJacobians(
      p, [&](const model::LoadPoint& q) { return contact.evaluate(q, false).force; });
  EXPECT_LT((analytic.d_position - fd.d_position).norm(), 1e-7 * analytic.d_position.norm());
  EXPECT_LT((analytic.d_velocity - fd.d_velocity).norm(), 1e-7 * analytic.d_velocity.norm());
}

}  // namespace
}  // namespace flexmoor::test
