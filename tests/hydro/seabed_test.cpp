// Seabed contact per unit length (MoorDyn v2's spring-damper with flexmoor's smooth saturated
// friction; docs/theory.md; MoorDyn's friction law: moordyn_friction_test.cpp) and bathymetry:
// closed forms at rest and sliding, and every derivative against central differences on a sloped
// bed.
#include <gtest/gtest.h>

#include <cmath>

#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"

namespace flexmoor::hydro {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// A chain lying still on a flat bed carries its submerged weight w per length at the
// penetration w / (k_b d): N = k_b delta d exactly; above the bed nothing acts.
TEST(SeabedContact, RestingLineIsCarriedAtItsPenetration) {
  SeabedProperties bed;
  const double d = 0.1, w = 1250.0, delta = w / (bed.stiffness * d);
  const SeabedPointLoad at_rest = seabedLoad(bed, delta, Vector3d::UnitZ(), d, Vector3d::Zero());
  EXPECT_TRUE(at_rest.contact);
  EXPECT_NEAR((at_rest.force - w * Vector3d::UnitZ()).norm(), 0.0, 1e-12 * w);
  const SeabedPointLoad above = seabedLoad(bed, -1e-3, Vector3d::UnitZ(), d, Vector3d::Ones());
  EXPECT_FALSE(above.contact);
  EXPECT_EQ(above.force.norm() + above.d_position.norm() + above.d_velocity.norm(), 0.0);
}

// A line laid exactly on the bed (delta = 0, a catenary start) feels no force but the bed's full
// stiffness k_b d, so the first Newton step of a static solve sinks it to its penetration
// w / (k_b d) instead of meeting a singular tangent.
TEST(SeabedContact, LineExactlyOnTheBedHasTheContactStiffness) {
  SeabedProperties bed;
  const double d = 0.1;
  const SeabedPointLoad on = seabedLoad(bed, 0.0, Vector3d::UnitZ(), d, Vector3d::Zero());
  EXPECT_TRUE(on.contact);
  EXPECT_EQ(on.force.norm(), 0.0);
  EXPECT_NEAR(on.d_position(2, 2), -bed.stiffness * d, 1e-9 * bed.stiffness * d);
}

// An integration point of a line laid on the bed is interpolated from its nodes' heights, so it
// lies within round-off of the bed, above or below it by chance: 2 ulp above a bed at -200 m it
// is in contact (the stiffness, no force); 1e-9 m above it is not.
TEST(SeabedContact, PointOnTheBedToRoundOffIsInContact) {
  SeabedProperties bed;
  const double d = 0.25, z = -200.0;
  const Bathymetry flat = Bathymetry::flat(-z);  // the bed at z
  const double above = std::nextafter(std::nextafter(z, 0.0), 0.0);
  const SeabedPointLoad on =
      seabedLoadAt(flat, bed, Vector3d(10.0, 0.0, above), d, Vector3d::Zero());
  EXPECT_TRUE(on.contact);
  EXPECT_EQ(on.force.norm(), 0.0);
  EXPECT_NEAR(on.d_position(2, 2), -bed.stiffness * d, 1e-9 * bed.stiffness * d);
  const SeabedPointLoad off =
      seabedLoadAt(flat, bed, Vector3d(10.0, 0.0, z + 1e-9), d, Vector3d::Zero());
  EXPECT_FALSE(off.contact);
  EXPECT_EQ(off.d_position.norm(), 0.0);
}

// Sliding at U >> v_s the friction is mu N against the motion, to (v_s / U)^2 / 2; at rest it is
// zero; a vertical velocity feels the bed's damping c_b d, not friction.
TEST(SeabedContact, SlidingLineIsResistedByMuTimesTheContactForce) {
  SeabedProperties bed;
  bed.friction = 0.6;
  const double d = 0.1, delta = 2e-2, N = bed.stiffness * delta * d, U = 1.0;  // past the ramp
  const Vector3d sliding(U, 0.0, 0.0);
  const SeabedPointLoad f = seabedLoad(bed, delta, Vector3d::UnitZ(), d, sliding);
  const double ratio = bed.slip_speed / U;
  EXPECT_NEAR(-f.force.x() / (bed.friction * N), 1.0, 0.5 * ratio * ratio * 1.01);
  EXPECT_NEAR(f.force.z(), N, 1e-12 * N);
  const SeabedPointLoad rising = seabedLoad(bed, delta, Vector3d::UnitZ(), d, Vector3d(0, 0, 0.01));
  EXPECT_NEAR(rising.force.z(), N - bed.damping * 0.01 * d, 1e-12 * N);
  EXPECT_EQ(rising.force.x(), 0.0);
}

// On a sloped bed (a plane through p0 with normal n), delta = n . (p0 - x): the derivatives in
// position and velocity against central differences, sliding and near rest; relative 1e-7.
TEST(SeabedContact, DerivativesMatchCentralDifferencesOnASlopedBed) {
  SeabedProperties bed;
  bed.friction = 0.4;
  const Bathymetry plane = Bathymetry::plane(-50.0, 0.05, -0.02);
  const Vector3d n = plane.normal(0.0, 0.0), p0(0.0, 0.0, -50.0);
  const double d = 0.12;
  const auto load = [&](const Vector3d& x, const Vector3d& v) {
    return seabedLoad(bed, n.dot(p0 - x), n, d, v);
  };
  const Vector3d x(3.0, -2.0, -50.0 + 0.05 * 3.0 - 0.02 * -2.0 - 4e-3);
  for (const Vector3d& v : {Vector3d(0.3, -0.2, 0.01), Vector3d(0.004, 0.002, -0.001)}) {
    const SeabedPointLoad L = load(x, v);
    ASSERT_TRUE(L.contact);
    Matrix3d dx, dv;
    for (int j = 0; j < 3; ++j) {
      const Vector3d ex = 1e-7 * Vector3d::Unit(j), ev = 1e-7 * Vector3d::Unit(j);
      dx.col(j) = (load(x + ex, v).force - load(x - ex, v).force) / 2e-7;
      dv.col(j) = (load(x, v + ev).force - load(x, v - ev).force) / 2e-7;
    }
    EXPECT_LT((L.d_position - dx).cwiseAbs().maxCoeff(), 1e-7 * dx.cwiseAbs().maxCoeff());
    EXPECT_LT((L.d_velocity - dv).cwiseAbs().maxCoeff(), 1e-7 * dv.cwiseAbs().maxCoeff());
  }
}

// A point touching down at speed: the force grows continuously from zero (MoorDyn's damping from
// delta = 0 on would jump by c_b |v_n| d), the damping reaching its full c_b over the first
// kDampingDepth d of penetration, and the derivatives there, in position included (the damping's
// share depends on delta), match central differences to 1e-7 relative.
TEST(SeabedContact, LandingLineMeetsAForceThatGrowsContinuously) {
  const SeabedProperties bed;
  const double d = 0.1, depth = kDampingDepth * d;
  const Vector3d landing(0.2, 0.0, -0.5);
  const auto normal = [&](double delta) {
    return seabedLoad(bed, delta, Vector3d::UnitZ(), d, landing).force.z();
  };
  EXPECT_EQ(normal(0.0), 0.0);
  EXPECT_NEAR(normal(1e-9), (bed.stiffness + bed.damping * 0.5 / depth) * 1e-9 * d, 1e-18);
  EXPECT_NEAR(normal(depth), (bed.stiffness * depth + bed.damping * 0.5) * d, 1e-9);
  EXPECT_NEAR(normal(2 * depth), (bed.stiffness * 2 * depth + bed.damping * 0.5) * d, 1e-9);
  const Vector3d x(1.0, 2.0, -0.4 * depth);
  const auto load = [&](const Vector3d& p, const Vector3d& v) {
    return seabedLoad(bed, -p.z(), Vector3d::UnitZ(), d, v);
  };
  const SeabedPointLoad L = load(x, landing);
  Matrix3d dx, dv;
  for (int j = 0; j < 3; ++j) {
    const Vector3d e = 1e-9 * Vector3d::Unit(j);
    dx.col(j) = (load(x + e, landing).force - load(x - e, landing).force) / 2e-9;
    dv.col(j) = (load(x, landing + e).force - load(x, landing - e).force) / 2e-9;
  }
  EXPECT_LT((L.d_position - dx).cwiseAbs().maxCoeff(), 1e-7 * dx.cwiseAbs().maxCoeff());
  EXPECT_LT((L.d_velocity - dv).cwiseAbs().maxCoeff(), 1e-7 * dv.cwiseAbs().maxCoeff());
}

// A grid holding a plane reproduces it exactly (bilinear interpolation is exact for it), with
// its gradient; beyond the edges the height is held.
TEST(Bathymetry, GridReproducesAPlaneAndHoldsItsEdges) {
  const Bathymetry plane = Bathymetry::plane(-100.0, 0.01, 0.03);
  std::vector<double> z;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i) z.push_back(plane.height(-20.0 + 10.0 * i, 5.0 * j));
  const Bathymetry grid = Bathymetry::grid(-20.0, 10.0, 5, 0.0, 5.0, 4, z);
  for (const auto& [x, y] : {std::pair(-13.0, 2.0), std::pair(7.5, 12.5), std::pair(19.0, 14.0)}) {
    EXPECT_NEAR(grid.height(x, y), plane.height(x, y), 1e-12);
    EXPECT_LT((grid.gradient(x, y) - plane.gradient(x, y)).norm(), 1e-12);
    EXPECT_LT((grid.normal(x, y) - plane.normal(x, y)).norm(), 1e-12);
  }
  EXPECT_NEAR(grid.height(-50.0, 2.0), plane.height(-20.0, 2.0), 1e-12);
  EXPECT_DOUBLE_EQ(Bathymetry::flat(320.0).height(1e3, -4e3), -320.0);
  EXPECT_LT((Bathymetry::flat(320.0).normal(0.0, 0.0) - Vector3d::UnitZ()).norm(), 1e-15);
}

}  // namespace
}  // namespace flexmoor::hydro
