// The load-point adapters of libhydro (MorisonLineLoad, BodyNodeLoad, SeabedLineLoad): their
// analytic Jacobians against central differences of their own evaluate (model::
// numericalJacobians, step 1e-6 of each vector's scale), at points in an Airy wave at finite
// depth with a heading (the sea of ocean_models.hpp), in a sheared current, just below the crest
// (Wheeler-stretched, above the mean level), a sphere piercing the surface, and a line in
// contact with a sloped bed.
//
// Reference: the central differences. The adapters' derivative in position goes through the
// flow's gradient, itself by central differences of Sea::at at 1e-4 / k (truncation ~1e-9 of the
// gradient); the whole evaluate is differenced here at the step of numericalJacobians, so the
// test fails on a missing or wrong chain term. Metric: max |J - J_fd| / max(max |J_fd|, |f| /
// (1 unit of the variable)), the floor covering derivatives that vanish. Tolerance 1e-8
// (measured: 4.3e-10 Morison, 7.4e-10 body, 3.4e-9 seabed; margin about 3).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>
#include <string>

#include "libhydro/loads/body_node_load.hpp"
#include "libhydro/loads/morison_line_load.hpp"
#include "libhydro/seabed/seabed_line_load.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::hydro {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

constexpr double kG = 9.80665, kRho = 1025.0, kDepth = 50.0, kTolerance = 1e-8;

std::shared_ptr<Sea> waveAndCurrent() { return test::waveAndCurrentSea(kDepth); }

// A 1/7 power-law current alone, 1.1 m/s at the surface (sheared: a derivative in z).
std::shared_ptr<Sea> currentOnly() {
  auto sea = std::make_shared<Sea>(Water{kRho, kDepth, kG});
  sea->setCurrent(CurrentProfile::powerLaw(1.1, 7.0, kDepth, -0.3));
  return sea;
}

double jacobianError(const Matrix3d& analytic, const Matrix3d& fd, double floor) {
  return (analytic - fd).cwiseAbs().maxCoeff() / std::max(fd.cwiseAbs().maxCoeff(), floor);
}

// Every derivative of `load` at `p` against numericalJacobians; returns the largest error.
template <class Load>
double worstJacobianError(const Load& load, const model::LoadPoint& p, const std::string& where) {
  const model::PointForce a = load.evaluate(p, true);
  const model::PointForce fd = model::numericalJacobians(
      p, [&](const model::LoadPoint& q) { return load.evaluate(q, false).force; });
  const double floor = std::max(a.force.norm(), 1e-300);
  EXPECT_GT(a.force.norm(), 0.0) << where;
  EXPECT_LT((a.force - fd.force).norm(), 1e-14 * floor) << where;
  const double errors[] = {jacobianError(a.d_position, fd.d_position, floor),
                           jacobianError(a.d_tangent, fd.d_tangent, floor),
                           jacobianError(a.d_velocity, fd.d_velocity, floor),
                           jacobianError(a.d_acceleration, fd.d_acceleration, floor)};
  const char* names[] = {"d_position", "d_tangent", "d_velocity", "d_acceleration"};
  for (int i = 0; i < 4; ++i) EXPECT_LT(errors[i], kTolerance) << where << ": " << names[i];
  return *std::max_element(std::begin(errors), std::end(errors));
}

model::LoadPoint linePoint(const Vector3d& position, double time) {
  model::LoadPoint p;
  p.position = position;
  p.velocity = Vector3d(0.3, -0.45, 0.12);
  p.acceleration = Vector3d(0.05, 0.2, -0.3);
  p.tangent = Vector3d(0.6, 0.3, 0.74).normalized();
  p.stretch = 1.003;
  p.time = time;
  p.element = 1;
  return p;
}

MorisonCoefficients rope() {
  MorisonCoefficients c;
  c.diameter = 0.12;
  c.cn = 1.2;
  c.ct = 0.01;
  c.ca = 1.0;
  c.ca_axial = 0.3;
  return c;
}

// A point at (x, y) `below` metres under the local surface at time t.
Vector3d belowSurface(const Sea& sea, double x, double y, double t, double below) {
  return {x, y, sea.elevation(Vector3d(x, y, 0.0), t) - below};
}

TEST(LoadAdapterJacobians, MorisonLineLoadMatchesCentralDifferences) {
  const auto waves = waveAndCurrent();
  const auto current = currentOnly();
  for (const auto tangential : {MorisonCoefficients::TangentialDragArea::Perimeter,
                                MorisonCoefficients::TangentialDragArea::Diameter}) {
    MorisonCoefficients c = rope();
    c.tangential_area = tangential;
    const MorisonLineLoad in_waves(waves, {std::nullopt, c});
    const MorisonLineLoad in_current(current, {std::nullopt, c});
    double worst = 0.0;
    worst = std::max(worst, worstJacobianError(in_waves, linePoint({12.0, -7.0, -14.0}, 1.3),
                                               "waves, 14 m down"));
    // Near a crest (eta ~ +0.7 m at x = 3.2, t = 0): 5 cm under the surface, above z = 0.
    const Vector3d crest = belowSurface(*waves, 3.2, 0.0, 0.0, 0.05);
    EXPECT_GT(crest.z(), 0.0);
    worst = std::max(worst, worstJacobianError(in_waves, linePoint(crest, 0.0), "under a crest"));
    worst = std::max(
        worst,
        worstJacobianError(in_waves, linePoint(belowSurface(*waves, -20.0, 9.0, 2.9, 0.3), 2.9),
                           "under a trough"));
    worst = std::max(worst, worstJacobianError(in_current, linePoint({4.0, 2.0, -41.0}, 0.0),
                                               "sheared current near the bed"));
    std::cout << "MorisonLineLoad: worst relative Jacobian error " << worst << '\n';
  }
  // Above the surface and on an element without a section: nothing.
  const MorisonLineLoad load(waves, {std::nullopt, rope()});
  model::LoadPoint dry = linePoint(belowSurface(*waves, 3.2, 0.0, 0.0, -0.01), 0.0);
  EXPECT_EQ(load.evaluate(dry, true).force.norm(), 0.0);
  model::LoadPoint unsectioned = linePoint({0.0, 0.0, -10.0}, 0.0);
  unsectioned.element = 0;
  EXPECT_EQ(load.evaluate(unsectioned, false).force.norm(), 0.0);
  unsectioned.element = 7;
  EXPECT_EQ(load.evaluate(unsectioned, false).force.norm(), 0.0);
}

model::LoadPoint nodePoint(const Vector3d& position, double time) {
  model::LoadPoint p;
  p.position = position;
  p.velocity = Vector3d(-0.2, 0.5, 0.3);
  p.acceleration = Vector3d(0.4, -0.1, 0.25);
  p.time = time;
  p.node = 3;
  return p;
}

TEST(LoadAdapterJacobians, BodyNodeLoadMatchesCentralDifferences) {
  const auto waves = waveAndCurrent();
  const auto current = currentOnly();
  const BodyNodeLoad buoy(3, PointBody::sphere(2.0, 0.7), waves);
  double worst = 0.0;
  worst = std::max(worst, worstJacobianError(buoy, nodePoint({8.0, 5.0, -9.0}, 0.7), "deep"));
  // Piercing the surface: centre 0.4 m under it (a cap), and 0.3 m above it (flow at the surface).
  worst = std::max(
      worst, worstJacobianError(buoy, nodePoint(belowSurface(*waves, -3.0, 1.0, 1.1, 0.4), 1.1),
                                "centre under the surface"));
  worst = std::max(
      worst, worstJacobianError(buoy, nodePoint(belowSurface(*waves, 6.0, -2.0, 4.0, -0.3), 4.0),
                                "centre above the surface"));
  const BodyNodeLoad clump(3, PointBody::sphere(0.8, 1.0, 0.5), current);
  worst = std::max(worst, worstJacobianError(clump, nodePoint({0.0, 0.0, -44.0}, 0.0),
                                             "sheared current near the bed"));
  std::cout << "BodyNodeLoad: worst relative Jacobian error " << worst << '\n';
  // Out of the water altogether: nothing.
  EXPECT_EQ(
      buoy.evaluate(nodePoint(belowSurface(*waves, 0.0, 0.0, 0.0, -1.5), 0.0), true).force.norm(),
      0.0);
}

TEST(LoadAdapterJacobians, SeabedLineLoadMatchesCentralDifferencesOnASlopedBed) {
  SeabedProperties properties;
  properties.friction = 0.5;
  const Bathymetry bed = Bathymetry::plane(-kDepth, 0.04, -0.03);
  const SeabedLineLoad load(bed, properties, {0.0, 0.12});
  double worst = 0.0;
  for (const Vector3d& velocity :
       {Vector3d(0.3, -0.2, 0.01), Vector3d(0.004, 0.002, -0.001), Vector3d(-1.2, 0.4, 0.0)}) {
    model::LoadPoint p = linePoint({20.0, -10.0, bed.height(20.0, -10.0) - 3e-3}, 0.0);
    p.velocity = velocity;
    worst = std::max(worst, worstJacobianError(load, p, "on the sloped bed"));
  }
  std::cout << "SeabedLineLoad: worst relative Jacobian error " << worst << '\n';
  // The penetration is measured along the bed's normal: on the plane it is n . (p0 - y), and at
  // rest the force is k_b delta d n.
  model::LoadPoint rest = linePoint({20.0, -10.0, bed.height(20.0, -10.0) - 3e-3}, 0.0);
  rest.velocity.setZero();
  const Vector3d n = bed.normal(20.0, -10.0);
  const double delta = n.dot(Vector3d(20.0, -10.0, bed.height(20.0, -10.0)) - rest.position);
  const Vector3d expected = properties.stiffness * delta * 0.12 * n;
  EXPECT_NEAR((load.evaluate(rest, false).force - expected).norm(), 0.0, 1e-12 * expected.norm());
  // Above the bed and on an element of width 0: nothing.
  rest.position.z() += 6e-3;
  EXPECT_EQ(load.evaluate(rest, true).force.norm(), 0.0);
  rest.position.z() -= 6e-3;
  rest.element = 0;
  EXPECT_EQ(load.evaluate(rest, true).force.norm(), 0.0);
}

}  // namespace
}  // namespace flexmoor::hydro
