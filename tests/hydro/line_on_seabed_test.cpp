// A line lying on a flat bed (MoorDyn v2's seabed contact through SeabedLineLoad, per
// unstretched length): statically, under gravity and the water's buoyancy (MorisonLineLoad), it
// delivers its submerged weight w = (rho_s - rho_w) g A per length to the bed at the penetration
// w / (k_b d); dragged along the bed at U well above the slip speed v_s it is resisted by
// mu w L U / sqrt(U^2 + v_s^2), within (v_s / U)^2 / 2 of mu w L; stretched, it is pushed out per
// unstretched length.
// A steel rod (d = 0.1 m, 7850 kg/m^3) 20 m long, five 3-node elements at 30 m depth; x and y
// held, z free; solved by Newton (solveStatic, increment below 1e-12 relative) from 1 mm inside the
// bed. The bed force is the seabed load alone integrated over the elements at the solution.
// Tolerances: 1e-6 required for the weight; measured 5e-13 (force) and 3e-12 (penetration
// at every node), held to 1e-10; the dragged line's friction against the smooth law likewise.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "libstruct/solve/static_solver.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;

constexpr double kDepth = 30.0, kLength = 20.0, kSteel = 7850.0;

struct RodOnTheBed {
  OceanLine line;
  double submerged_weight = 0.0;  // w, per unit length
  double width = 0.0;             // d
};

RodOnTheBed rodOnTheBed(double friction) {
  OceanLineInputs in;
  in.start = Vector3d(0.0, 0.0, -kDepth);
  in.end = Vector3d(kLength, 0.0, -kDepth);
  in.elements = 5;
  in.nodes_per_element = 3;
  in.youngs_modulus = 2.0e11;
  in.density = kSteel;
  in.morison.diameter = 0.1;
  in.morison.cn = 1.2;
  in.morison.ca = 1.0;
  in.sea = stillWater(kDepth);
  in.bed = hydro::Bathymetry::flat(kDepth);
  in.bed_properties.friction = friction;
  RodOnTheBed rod{makeOceanLine(in), 0.0, in.morison.diameter};
  model::Model& m = *rod.line.model;
  m.setGravity(Vector3d(0.0, 0.0, -kStandardGravity));
  for (int n : rod.line.nodes) {
    m.constrain(n, 0);
    m.constrain(n, 1);
  }
  m.numberEquations();
  const double area = 0.25 * std::acos(-1.0) * rod.width * rod.width;
  rod.submerged_weight = (kSteel - kSeaWaterDensity) * kStandardGravity * area;
  return rod;
}

// The seabed load (the model's second line load) alone, summed over the elements.
Vector3d bedForce(const model::Model& m, const model::State& s) {
  Vector3d total = Vector3d::Zero();
  Eigen::VectorXd p;
  for (int e = 0; e < m.elementCount(); ++e) {
    m.element(e).lineLoad({m.reference(), s, e}, *m.lineLoads()[1], p, nullptr);
    total += Eigen::Map<const Eigen::Matrix3Xd>(p.data(), 3, p.size() / 3).rowwise().sum();
  }
  return s.load_factor * total;
}

model::State restingState(const RodOnTheBed& rod, const model::Assembler& assembler) {
  model::State s = rod.line.model->initialState();
  s.displacement.row(2).setConstant(-1e-3);
  solve::StaticOptions options;
  // The residual test is relative to max(|P|, |F|), and here P (weight, buoyancy, bed) sums to
  // zero at every node with F = 0: converge on the displacement alone (the problem is linear in
  // z, so Newton lands in one iteration and the next one measures it).
  options.convergence.use_residual = false;
  options.convergence.displacement_tolerance = 1e-12;
  solve::solveStatic(assembler, s, options);
  return s;
}

TEST(LineOnSeabed, RestingLineDeliversItsSubmergedWeightAtItsPenetration) {
  const RodOnTheBed rod = rodOnTheBed(0.0);
  const model::Assembler assembler(*rod.line.model);
  const model::State s = restingState(rod, assembler);
  const double wL = rod.submerged_weight * kLength;
  const Vector3d bed = bedForce(*rod.line.model, s);
  const double penetration =
      rod.submerged_weight / (hydro::SeabedProperties().stiffness * rod.width);
  double worst_penetration = 0.0;
  for (int n : rod.line.nodes)
    worst_penetration =
        std::max(worst_penetration, std::abs(-s.displacement(2, n) / penetration - 1.0));
  std::cout << "resting rod: bed force / w L - 1 = " << bed.z() / wL - 1.0
            << ", worst penetration / (w / (k_b d)) - 1 = " << worst_penetration << '\n';
  EXPECT_NEAR(bed.z() / wL, 1.0, 1e-10);
  EXPECT_LT(std::abs(bed.x()) + std::abs(bed.y()), 1e-12 * wL);
  EXPECT_LT(worst_penetration, 1e-10);
}

TEST(LineOnSeabed, DraggedLineIsResistedByMuTimesItsSubmergedWeight) {
  const double mu = 0.6, U = 1.0;
  const RodOnTheBed rod = rodOnTheBed(mu);
  const model::Assembler assembler(*rod.line.model);
  model::State s = restingState(rod, assembler);  // friction is nothing at rest
  s.velocity.row(0).setConstant(U);
  const Vector3d bed = bedForce(*rod.line.model, s);
  const double v_s = hydro::SeabedProperties().slip_speed, wL = rod.submerged_weight * kLength;
  const double smooth = mu * wL * U / std::sqrt(U * U + v_s * v_s);
  std::cout << "dragged rod: friction / (mu w L) = " << -bed.x() / (mu * wL)
            << ", / smooth law - 1 = " << -bed.x() / smooth - 1.0 << '\n';
  EXPECT_NEAR(-bed.x() / smooth, 1.0, 1e-6);                                 // the smooth law
  EXPECT_NEAR(-bed.x() / (mu * wL), 1.0, 0.5 * v_s * v_s / (U * U) * 1.01);  // its limit
  EXPECT_NEAR(bed.z() / wL, 1.0, 1e-10);  // a horizontal velocity leaves the contact force alone
}

// Per unstretched length (MoorDyn v2's convention): the rod stretched 1% along x and pushed 2 mm
// into the bed at every node (more than the 1 mm over which the damping comes in; at rest) is
// pushed out by k_b delta d per unstretched length, k_b delta d L0 in all (the integrand is
// constant: Gauss integration exact), not by k_b delta d times the stretched length 1.01 L0.
// Tolerance 1.2e-13 relative (measured -6.1e-14: the penetration is the difference of two heights
// 30 m down); per deformed length it would be +1%.
TEST(LineOnSeabed, StretchedLineIsPushedOutPerUnstretchedLength) {
  const RodOnTheBed rod = rodOnTheBed(0.0);
  const model::Model& m = *rod.line.model;
  const double strain = 0.01, delta = 2e-3;
  model::State s = m.initialState();
  for (int n : rod.line.nodes) {
    s.displacement(0, n) = strain * m.reference()(0, n);
    s.displacement(2, n) = -delta;
  }
  s.load_factor = 1.0;
  const double expected = hydro::SeabedProperties().stiffness * delta * rod.width * kLength;
  const Vector3d bed = bedForce(m, s);
  std::cout << "stretched rod: bed force / (k_b delta d L0) - 1 = " << bed.z() / expected - 1.0
            << '\n';
  EXPECT_NEAR(bed.z() / expected, 1.0, 1.2e-13);
  EXPECT_LT(std::abs(bed.x()) + std::abs(bed.y()), 1.2e-13 * expected);
}

}  // namespace
}  // namespace flexmoor::test
