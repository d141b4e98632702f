// Morison's load on a line per unit length (Appendix E; docs/theory.md) and on a point body: closed
// forms for a line towed broadside and along its axis, accelerated through still water and
// struck by an accelerating flow; every derivative against central differences.
#include "libhydro/loads/morison.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>

#include "libhydro/loads/point_body.hpp"

namespace flexmoor::hydro {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

const double kPi = std::acos(-1.0);
constexpr double kRho = 1025.0, kG = 9.80665;

MorisonCoefficients chain() {
  MorisonCoefficients c;
  c.diameter = 0.09;
  c.cn = 1.2;
  c.ct = 0.008;
  c.ca = 1.0;
  c.ca_axial = 0.5;
  return c;
}

const Vector3d kZero = Vector3d::Zero();

// A line along x towed at U through still water: broadside (along y) it feels 1/2 rho d Cn U^2
// against the motion, along its axis 1/2 rho (pi d) Ct U^2 (MoorDyn's area) or 1/2 rho d Ct U^2
// (the dissertation's, Eq. E.2). Exact to round-off (1e-12 relative).
TEST(Morison, TowedLineFeelsNormalAndTangentialDrag) {
  const MorisonCoefficients c = chain();
  const double U = 1.7, d = c.diameter;
  const Vector3d t = Vector3d::UnitX();
  const Vector3d broadside =
      morisonLoad(c, kRho, t, U * Vector3d::UnitY(), kZero, kZero, kZero).force;
  EXPECT_NEAR((broadside + 0.5 * kRho * d * c.cn * U * U * Vector3d::UnitY()).norm(), 0.0,
              1e-12 * broadside.norm());
  const Vector3d axial = morisonLoad(c, kRho, t, U * t, kZero, kZero, kZero).force;
  EXPECT_NEAR((axial + 0.5 * kRho * kPi * d * c.ct * U * U * t).norm(), 0.0, 1e-12 * axial.norm());
  MorisonCoefficients dissertation = c;
  dissertation.tangential_area = MorisonCoefficients::TangentialDragArea::Diameter;
  const Vector3d axial_d = morisonLoad(dissertation, kRho, t, U * t, kZero, kZero, kZero).force;
  EXPECT_NEAR(axial_d.x() / axial.x(), 1.0 / kPi, 1e-14);
  // Oblique: the normal and tangential parts of the relative velocity are dragged separately.
  const Vector3d oblique_velocity(U, U, 0.0);
  const Vector3d oblique = morisonLoad(c, kRho, t, oblique_velocity, kZero, kZero, kZero).force;
  EXPECT_NEAR((oblique - broadside - axial).norm(), 0.0, 1e-12 * oblique.norm());
}

// A line accelerated through still water carries rho A Ca (normal) and rho A CaAx (axial) along;
// a flow accelerating past a fixed line pushes it with rho A (1 + Ca) a (Froude-Krylov + added).
TEST(Morison, AddedMassAndFluidInertia) {
  const MorisonCoefficients c = chain();
  const double area = 0.25 * kPi * c.diameter * c.diameter, A = 0.8;
  const Vector3d t = Vector3d(1.0, 2.0, -0.5).normalized();
  const Vector3d n = t.cross(Vector3d::UnitZ()).normalized();
  const Vector3d normal = morisonLoad(c, kRho, t, kZero, A * n, kZero, kZero).force;
  EXPECT_NEAR((normal + kRho * area * c.ca * A * n).norm(), 0.0, 1e-12 * normal.norm());
  const Vector3d axial = morisonLoad(c, kRho, t, kZero, A * t, kZero, kZero).force;
  EXPECT_NEAR((axial + kRho * area * c.ca_axial * A * t).norm(), 0.0, 1e-12 * axial.norm());
  const Vector3d pushed = morisonLoad(c, kRho, t, kZero, kZero, kZero, A * n).force;
  EXPECT_NEAR((pushed - kRho * area * (1.0 + c.ca) * A * n).norm(), 0.0, 1e-12 * pushed.norm());
  const Matrix3d M = addedMassPerLength(c, kRho, t);
  EXPECT_LT((M - M.transpose()).norm(), 1e-12 * M.norm());
  EXPECT_NEAR((M * t).norm(), kRho * area * c.ca_axial, 1e-12 * M.norm());
}

// Central difference of a vector function of one 3-vector argument.
Matrix3d centralDifference(const std::function<Vector3d(const Vector3d&)>& f, const Vector3d& x,
                           double step) {
  Matrix3d J;
  for (int j = 0; j < 3; ++j) {
    const Vector3d e = step * Vector3d::Unit(j);
    J.col(j) = (f(x + e) - f(x - e)) / (2.0 * step);
  }
  return J;
}

// Every derivative of the line load against central differences (step 1e-6 of the argument's
// scale; truncation ~1e-12), away from v_r = 0 and at flows of both signs; relative to the
// largest entry, 1e-7.
TEST(Morison, EveryDerivativeMatchesCentralDifferences) {
  const MorisonCoefficients c = chain();
  const Vector3d t = Vector3d(0.3, -0.4, 0.87).normalized();
  const Vector3d ud(0.4, -1.1, 0.2), udd(0.3, 0.5, -0.9), v(-0.6, 0.7, 0.35), a(0.2, -0.1, 0.6);
  const MorisonPointLoad L = morisonLoad(c, kRho, t, ud, udd, v, a);
  const auto check = [&](const Matrix3d& analytic,
                         const std::function<Vector3d(const Vector3d&)>& f, const Vector3d& x,
                         const char* what) {
    const Matrix3d fd = centralDifference(f, x, 1e-6);
    EXPECT_LT((analytic - fd).cwiseAbs().maxCoeff(), 1e-7 * std::max(1.0, fd.cwiseAbs().maxCoeff()))
        << what << "\nanalytic\n"
        << analytic << "\nfd\n"
        << fd;
  };
  check(
      L.d_velocity, [&](const Vector3d& x) { return morisonLoad(c, kRho, t, x, udd, v, a).force; },
      ud, "d/du'");
  check(
      L.d_acceleration,
      [&](const Vector3d& x) { return morisonLoad(c, kRho, t, ud, x, v, a).force; }, udd, "d/du''");
  check(
      L.d_tangent, [&](const Vector3d& x) { return morisonLoad(c, kRho, x, ud, udd, v, a).force; },
      t, "d/dt");
  check(
      L.d_fluid_velocity,
      [&](const Vector3d& x) { return morisonLoad(c, kRho, t, ud, udd, x, a).force; }, v, "d/dv");
  check(
      L.d_fluid_acceleration,
      [&](const Vector3d& x) { return morisonLoad(c, kRho, t, ud, udd, v, x).force; }, a, "d/da");
}

// A sphere's submerged cap: none above, all below, half at the surface; dV/d depth is the
// waterplane area pi (R^2 - depth^2).
TEST(PointBody, SphereSubmergedVolumeIsItsCap) {
  const PointBody b = PointBody::sphere(2.0, 0.6);
  EXPECT_EQ(submergedVolume(b, -1.5).volume, 0.0);
  EXPECT_DOUBLE_EQ(submergedVolume(b, 1.5).volume, b.volume);
  EXPECT_NEAR(submergedVolume(b, 0.0).volume, 0.5 * b.volume, 1e-14 * b.volume);
  for (double depth : {-0.7, 0.0, 0.4}) {
    EXPECT_NEAR(submergedVolume(b, depth).d_elevation, kPi * (1.0 - depth * depth), 1e-12);
    const double h = 1e-6;
    const double fd =
        (submergedVolume(b, depth + h).volume - submergedVolume(b, depth - h).volume) / (2.0 * h);
    EXPECT_NEAR(submergedVolume(b, depth).d_elevation, fd, 1e-8);
  }
}

// A deeply submerged sphere: buoyancy rho g V, drag 1/2 rho Cd (pi D^2 / 4) U^2, added mass
// rho V Ca; a half-submerged one carries half of each. Every derivative against differences.
TEST(PointBody, LoadsAndDerivativesOfASphere) {
  const PointBody b = PointBody::sphere(1.2, 0.6);
  const double U = 0.9;
  const PointBodyLoad deep =
      pointBodyLoad(b, kRho, kG, 5.0, U * Vector3d::UnitX(), kZero, kZero, kZero);
  const double drag = 0.5 * kRho * 0.6 * 0.25 * kPi * 1.44 * U * U;
  EXPECT_NEAR((deep.force - Vector3d(-drag, 0.0, kRho * kG * b.volume)).norm(), 0.0,
              1e-12 * deep.force.norm());
  const PointBodyLoad half =
      pointBodyLoad(b, kRho, kG, 0.0, U * Vector3d::UnitX(), kZero, kZero, kZero);
  EXPECT_NEAR((half.force - 0.5 * deep.force).norm(), 0.0, 1e-12 * deep.force.norm());

  const double depth = 0.25;
  const Vector3d ud(0.4, -1.1, 0.2), udd(0.3, 0.5, -0.9), v(-0.6, 0.7, 0.35), a(0.2, -0.1, 0.6);
  const PointBodyLoad L = pointBodyLoad(b, kRho, kG, depth, ud, udd, v, a);
  const auto load = [&](double dep, const Vector3d& x1, const Vector3d& x2, const Vector3d& x3,
                        const Vector3d& x4) {
    return pointBodyLoad(b, kRho, kG, dep, x1, x2, x3, x4).force;
  };
  const double tol = 1e-7 * std::max(1.0, L.force.norm());
  EXPECT_LT(
      (L.d_velocity -
       centralDifference([&](const Vector3d& x) { return load(depth, x, udd, v, a); }, ud, 1e-6))
          .norm(),
      tol);
  EXPECT_LT(
      (L.d_acceleration -
       centralDifference([&](const Vector3d& x) { return load(depth, ud, x, v, a); }, udd, 1e-6))
          .norm(),
      tol);
  EXPECT_LT(
      (L.d_fluid_velocity -
       centralDifference([&](const Vector3d& x) { return load(depth, ud, udd, x, a); }, v, 1e-6))
          .norm(),
      tol);
  EXPECT_LT(
      (L.d_fluid_acceleration -
       centralDifference([&](const Vector3d& x) { return load(depth, ud, udd, v, x); }, a, 1e-6))
          .norm(),
      tol);
  const Vector3d d_depth =
      (load(depth + 1e-6, ud, udd, v, a) - load(depth - 1e-6, ud, udd, v, a)) / 2e-6;
  EXPECT_LT((L.d_depth - d_depth).norm(), tol);
}

}  // namespace
}  // namespace flexmoor::hydro
