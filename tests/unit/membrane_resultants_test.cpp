// The in-plane principal resultants (apps/output/membrane_resultants.cpp): a tensor
// R diag(a, b, 0) R^T in a plane of any orientation R, with known a and b, against a and b, on
// both of its paths (the plane's own 2 x 2 problem, and the eigensolver for a nearly uniaxial
// tensor). Tolerance 1e-13 of the larger magnitude (the tensor itself carries round-off of
// ~1e-16 of it from the rotation).
#include "apps/output/membrane_resultants.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace flexmoor::test {
namespace {

element::ElementResult onePoint(const Eigen::Matrix3d& n) {
  element::ElementResult r;
  r.point_resultant.push_back(n);
  return r;
}

TEST(MembraneResultants, PrincipalValuesOfTensorsInRotatedPlanes) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // isotropic, general, near-uniaxial on both sides of the fast path's limit, uniaxial, shear
  const std::pair<double, double> cases[] = {{3.0, 3.0},   {5.0, -2.0},  {1.0, 2e-5},
                                             {1.0, 5e-6},  {1.0, 0.0},   {-4.0, 0.0},
                                             {2.0, -2.0},  {1e3, 1e3 * (1 + 1e-9)}};
  for (const auto& [a, b] : cases) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Matrix3d R =
          Eigen::Quaterniond(unit(random), unit(random), unit(random), unit(random))
              .normalized()
              .toRotationMatrix();
      const Eigen::Matrix3d n = R * Eigen::Vector3d(a, b, 0.0).asDiagonal() * R.transpose();
      const auto p = app::principalResultants(onePoint(n));
      ASSERT_TRUE(p.has_value());
      const double tolerance = 1e-13 * std::max(std::abs(a), std::abs(b));
      EXPECT_NEAR(p->first, std::max(a, b), tolerance) << a << ", " << b;
      EXPECT_NEAR(p->second, std::min(a, b), tolerance) << a << ", " << b;
    }
  }
  EXPECT_EQ(app::principalResultants(onePoint(Eigen::Matrix3d::Zero()))->first, 0.0);
  EXPECT_FALSE(app::principalResultants(element::ElementResult{}).has_value());
}

}  // namespace
}  // namespace flexmoor::test
