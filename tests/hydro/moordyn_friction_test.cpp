// MoorDyn's seabed friction (libhydro/seabed/seabed_friction.hpp, `friction: {law: moordyn}`)
// against MoorDyn-C v2's bottom contact as written in its source/Line.cpp (Line::getStateDeriv),
// evaluated by hand at one of its nodes: B_z = (k_b delta - c_b v_z) d l, FrictionMax =
// mu |B_z|, FrictionForce = mu FricDamp |v_h|, set to FrictionMax where it exceeds
// StatDynFricScale FrictionMax, against the horizontal velocity; flexmoor's force per unit
// length is that over the node's length l. Its derivatives against central differences, and the
// case reader's law and node lengths.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/case/case_reader.hpp"
#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libhydro/seabed/seabed_friction.hpp"
#include "libhydro/seabed/seabed_line_load.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::hydro {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// MoorDyn's node force, by hand from its source, at a node of length l sliding at (vx, vy, vz)
// a depth delta into a flat bed: {friction x, friction y, B_z}.
Vector3d moordynNodeForce(double kb, double cb, double d, double l, double delta, double mu,
                          double fric_damp, double scale, const Vector3d& v) {
  const double Bz = (delta * kb - v.z() * cb) * d * l;
  const double friction_max = std::abs(Bz) * mu;
  const double bottom_vel = std::sqrt(v.x() * v.x() + v.y() * v.y());
  double friction = bottom_vel * mu * fric_damp;
  if (friction > scale * friction_max) friction = friction_max;
  if (bottom_vel == 0.0) return {0.0, 0.0, Bz};
  return {-friction * v.x() / bottom_vel, -friction * v.y() / bottom_vel, Bz};
}

// A 0.09 m chain 2 cm into the bed, past the damping's ramp (N = 5,400 N/m at rest), nodes 10 m apart, mu 0.5,
// FricDamp 54,000 N s/m so that the damper saturates at |v_h| = s N l / FricDamp = 1 m/s (s = 1) or 1.5 m/s
// (s = 1.5): speeds from rest to well above it, sliding obliquely and settling (v_z < 0, which
// raises N through the bed's damping). Relative 1e-15 of the force (round-off; measured 8.8e-17).
TEST(MoorDynFriction, ForceIsMoorDynsNodeForceOverItsLength) {
  SeabedProperties bed;
  bed.friction = 0.5;
  bed.friction_law = FrictionLaw::MoorDyn;
  bed.friction_damping = 54000.0;
  const double d = 0.09, l = 10.0, delta = 2e-2;
  int saturated = 0, damped = 0;
  for (const double scale : {1.0, 1.5}) {
    bed.static_dynamic_scale = scale;
    for (const double speed : {0.0, 0.05, 0.3, 0.9, 1.2, 1.45, 1.6, 4.0})
      for (const double vz : {0.0, -0.01}) {
        const Vector3d v(0.8 * speed, -0.6 * speed, vz);
        const SeabedPointLoad f = seabedLoad(bed, delta, Vector3d::UnitZ(), d, v, l);
        const Vector3d node = moordynNodeForce(bed.stiffness, bed.damping, d, l, delta,
                                               bed.friction, bed.friction_damping, scale, v);
        const double size = node.norm() / l;
        EXPECT_NEAR(f.force.x(), node.x() / l, 1e-15 * size) << scale << " " << speed << " " << vz;
        EXPECT_NEAR(f.force.y(), node.y() / l, 1e-15 * size) << scale << " " << speed << " " << vz;
        EXPECT_NEAR(f.force.z(), node.z() / l, 1e-15 * size) << scale << " " << speed << " " << vz;
        const double friction = std::hypot(node.x(), node.y());
        if (friction > 0.0 && friction == bed.friction * std::abs(node.z())) ++saturated;
        if (friction > 0.0 && friction < bed.friction * std::abs(node.z())) ++damped;
      }
  }
  EXPECT_GE(saturated, 6);  // the cases cover both branches
  EXPECT_GE(damped, 6);
}

// Below the saturation speed the friction is the damper's alone, mu FricDamp / l v_h, whatever
// the bed's force; above it mu N, whatever the speed: two closed forms.
TEST(MoorDynFriction, DamperBelowSaturationAndCoulombAbove) {
  SeabedProperties bed;
  bed.friction = 0.6;
  bed.friction_law = FrictionLaw::MoorDyn;
  const double d = 0.1, l = 5.0;
  for (const double delta : {1e-3, 4e-3}) {
    const double N = bed.stiffness * delta * d;
    const double slow = 1e-3, fast = 1e3;  // 200 N s/m over 5 m: saturation at N / 40 m/s
    const SeabedPointLoad a = seabedLoad(bed, delta, Vector3d::UnitZ(), d, {slow, 0.0, 0.0}, l);
    EXPECT_NEAR(a.force.x(), -bed.friction * 200.0 / l * slow, 1e-15);
    const SeabedPointLoad b = seabedLoad(bed, delta, Vector3d::UnitZ(), d, {0.0, fast, 0.0}, l);
    EXPECT_NEAR(b.force.y(), -bed.friction * N, 1e-12 * N);
    EXPECT_EQ(b.force.x(), 0.0);
  }
}

// The derivatives in position and velocity on a sloped bed (friction along its plane), on the
// damper branch, the saturated one and at rest, against central differences (step 1e-7): relative
// 3e-8 in position (measured 1.2e-8, the differences' round-off on the bed's stiffness) and 1e-9
// in velocity (measured 3.4e-10).
TEST(MoorDynFriction, DerivativesMatchCentralDifferencesOnASlopedBed) {
  SeabedProperties bed;
  bed.friction = 0.4;
  bed.friction_law = FrictionLaw::MoorDyn;
  bed.friction_damping = 3000.0;
  bed.static_dynamic_scale = 1.2;
  const double d = 0.12, l = 8.0;
  const Bathymetry plane = Bathymetry::plane(-50.0, 0.05, -0.02);
  const Vector3d n = plane.normal(0.0, 0.0), p0(0.0, 0.0, -50.0);
  const auto load = [&](const Vector3d& x, const Vector3d& v) {
    return seabedLoad(bed, n.dot(p0 - x), n, d, v, l);
  };
  const Vector3d x(3.0, -2.0, -50.0 + 0.05 * 3.0 - 0.02 * -2.0 - 4e-3);
  // N = 1440 N/m: saturation at s N l / c = 4.6 m/s along the bed.
  for (const Vector3d& v : {Vector3d(0.3, -0.2, 0.01), Vector3d(9.0, 4.0, -0.02),
                            Vector3d(0.0, 0.0, 0.0), Vector3d(0.004, 0.002, -0.001)}) {
    const SeabedPointLoad L = load(x, v);
    ASSERT_TRUE(L.contact);
    Matrix3d dx, dv;
    for (int j = 0; j < 3; ++j) {
      const Vector3d e = 1e-7 * Vector3d::Unit(j);
      dx.col(j) = (load(x + e, v).force - load(x - e, v).force) / 2e-7;
      dv.col(j) = (load(x, v + e).force - load(x, v - e).force) / 2e-7;
    }
    EXPECT_LT((L.d_position - dx).cwiseAbs().maxCoeff(), 3e-8 * dx.cwiseAbs().maxCoeff())
        << v.transpose();
    EXPECT_LT((L.d_velocity - dv).cwiseAbs().maxCoeff(), 1e-9 * dv.cwiseAbs().maxCoeff())
        << v.transpose();
  }
}

// The laws' own derivatives in N and u' (before the contact's chain rule), both branches:
// central differences, df/dN within 1e-11 (measured 3.9e-12), df/du' within 5e-9 of its largest
// entry (measured 1.8e-9).
TEST(MoorDynFriction, LawDerivativesInNormalForceAndVelocity) {
  const Vector3d n = Vector3d(0.1, -0.05, 1.0).normalized();
  for (const Vector3d& v : {Vector3d(0.02, 0.01, 0.0), Vector3d(3.0, -1.0, 0.2)}) {
    const double N = 500.0;
    const auto f = [&](double normal, const Vector3d& u) {
      return moordynFriction(0.5, 200.0, 1.0, normal, n, u);
    };
    const FrictionForce F = f(N, v);
    const Vector3d dN = (f(N + 1e-3, v).force - f(N - 1e-3, v).force) / 2e-3;
    Matrix3d dv;
    for (int j = 0; j < 3; ++j) {
      const Vector3d e = 1e-7 * Vector3d::Unit(j);
      dv.col(j) = (f(N, v + e).force - f(N, v - e).force) / 2e-7;
    }
    EXPECT_LT((F.d_normal - dN).norm(), 1e-11) << v.transpose();
    EXPECT_LT((F.d_velocity - dv).cwiseAbs().maxCoeff(), 5e-9 * dv.cwiseAbs().maxCoeff())
        << v.transpose();
  }
}

// A case's `friction: {law: moordyn, ...}` reaches the bed's line load with each element's node
// spacing as MoorDyn's node length (a 40 m line of 4 three-node elements: 5 m), and a plain
// `friction: 0.5` stays flexmoor's Coulomb law (mu N / sqrt(1 + (v_s / U)^2) at U = 1 m/s).
TEST(MoorDynFriction, CaseSelectsTheLawAndSpreadsTheDampingOverTheNodeSpacing) {
  const auto bedCase = [](const std::string& seabed) {
    return std::string(R"(units: SI
water: {density: 1025 kg/m^3, depth: 50 m}
seabed: )") +
           seabed + R"(
materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  chain: {material: steel, area: 1.0e-3 m^2, density: 7850 kg/m^3,
          hydro: {diameter: 0.1 m, Cn: 1.2, Ca: 1.0}}
lines:
  - {name: laid, from: [0, 0, -50 m], to: [40 m, 0, -50 m], elements: 4, order: 3,
     section: chain}
supports:
  - {node: laid.start, fix: [x, y, z]}
  - {nodes: laid, fix: [y, z]}
steps:
  - static: {}
)";
  };
  const auto lineLoad = [](const app::Case& c) {
    for (const auto& load : c.model->lineLoads())
      if (const auto* bed = dynamic_cast<const SeabedLineLoad*>(load.get())) return bed;
    return static_cast<const SeabedLineLoad*>(nullptr);
  };
  model::LoadPoint p;
  p.element = 2;
  p.position = {22.0, 0.0, -50.002};  // 2 mm in: N = 3e6 * 2e-3 * 0.1 = 600 N/m
  p.velocity = {0.1, 0.0, 0.0};
  const app::Case moordyn = app::readCase(
      test::writeCase("moordyn-friction.yaml",
                      bedCase("{friction: {law: moordyn, coefficient: 0.5, damping: 1000 N*s/m, "
                              "static_dynamic_scale: 1.0}}")));
  const SeabedLineLoad* bed = lineLoad(moordyn);
  ASSERT_NE(bed, nullptr);
  // The damper, 0.5 x 1000 / 5 m x 0.1 m/s = 10 N/m, below its cap 0.5 x 600 N/m.
  EXPECT_NEAR(bed->evaluate(p, false).force.x(), -0.5 * 1000.0 / 5.0 * 0.1, 1e-9);
  p.velocity = {1.0, 0.0, 0.0};
  const app::Case coulomb =
      app::readCase(test::writeCase("coulomb-friction.yaml", bedCase("{friction: 0.5}")));
  EXPECT_NEAR(lineLoad(coulomb)->evaluate(p, false).force.x(),
              -0.5 * 600.0 / std::sqrt(1.0 + 0.01 * 0.01), 1e-9);
}

}  // namespace
}  // namespace flexmoor::hydro
