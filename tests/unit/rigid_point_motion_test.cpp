// RigidPointMotion (libstruct/model/rigid_point_motion.hpp): the displacement of a point carried
// by a rigid platform with a prescribed 6-dof motion, and its derivatives.
#include "libstruct/model/rigid_point_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace flexmoor::model {
namespace {

using Motions = std::array<std::shared_ptr<const TimeFunction>, 6>;

Motions allSix() {
  const auto sine = [](double a, double period, double phase) {
    return std::make_shared<SineFunction>(0.0, a, period, phase);
  };
  // surge, sway, heave (m); roll, pitch, yaw (rad, 6 to 17 degrees)
  return {sine(2.0, 10.0, 0.0), sine(1.0, 7.0, 0.4),  sine(0.5, 13.0, 1.1),
          sine(0.2, 9.0, 0.3),  sine(0.1, 11.0, 2.0), sine(0.3, 17.0, -0.7)};
}

Eigen::Matrix3d rotation(int axis, double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

// Reference: Eigen's AngleAxis rotations and the angular velocity from the Euler rates,
// omega = yaw' e_z + pitch' Rz e_y + roll' Rz Ry e_x, so v = v_ref + omega x (R arm).
TEST(RigidPointMotion, PositionAndVelocityAreThoseOfTheRigidMotion) {
  const Motions m = allSix();
  const Eigen::Vector3d arm(20.434, 35.393, -14.0);
  const RigidPointMotion x(m, arm, 0, 0.0), y(m, arm, 1, 0.0), z(m, arm, 2, 0.0);
  for (double t : {0.0, 1.3, 4.7, 12.1}) {
    const Eigen::Matrix3d rz = rotation(2, m[5]->value(t)), ry = rotation(1, m[4]->value(t)),
                          rx = rotation(0, m[3]->value(t));
    const Eigen::Vector3d translation(m[0]->value(t), m[1]->value(t), m[2]->value(t));
    const Eigen::Vector3d moved = rz * ry * rx * arm;
    const Eigen::Vector3d expected = translation + moved - arm;
    const Eigen::Vector3d omega = m[5]->rate(t) * Eigen::Vector3d::UnitZ() +
                                  m[4]->rate(t) * rz * Eigen::Vector3d::UnitY() +
                                  m[3]->rate(t) * rz * ry * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d velocity =
        Eigen::Vector3d(m[0]->rate(t), m[1]->rate(t), m[2]->rate(t)) + omega.cross(moved);
    const Eigen::Vector3d got(x.value(t), y.value(t), z.value(t));
    const Eigen::Vector3d got_rate(x.rate(t), y.rate(t), z.rate(t));
    // Both exact: round-off of 3x3 products of a 40 m arm, about 1e-14 m; held to 1e-12.
    EXPECT_LT((got - expected).norm(), 1e-12) << "t = " << t;
    EXPECT_LT((got_rate - velocity).norm(), 1e-12) << "t = " << t;
  }
}

// Reference: central differences of value and rate, h = 1e-4 s (error h^2 / 6 times the third
// derivative, about 1e-9 here); held to 1e-7 m/s and m/s^2.
TEST(RigidPointMotion, DerivativesMatchFiniteDifferences) {
  const Eigen::Vector3d arm(-40.868, 0.0, -14.0);
  const double h = 1e-4;
  for (int k = 0; k < 3; ++k) {
    const RigidPointMotion f(allSix(), arm, k, 3.0);
    for (double t : {0.0, 2.2, 8.9}) {
      EXPECT_NEAR(f.rate(t), (f.value(t + h) - f.value(t - h)) / (2 * h), 1e-7);
      EXPECT_NEAR(f.acceleration(t), (f.rate(t + h) - f.rate(t - h)) / (2 * h), 1e-7);
    }
  }
}

// Pure surge: x = offset + A sin(2 pi t / T) exactly, y and z still; the period the surge's.
TEST(RigidPointMotion, SurgeAloneIsTheSine) {
  Motions m;
  m[0] = std::make_shared<SineFunction>(0.0, 2.0, 10.0, 0.0);
  const Eigen::Vector3d arm(20.434, 35.393, -14.0);
  const RigidPointMotion x(m, arm, 0, 5.0), z(m, arm, 2, -1.0);
  const double w = 2.0 * std::acos(-1.0) / 10.0;
  for (double t : {0.0, 2.5, 7.1}) {
    EXPECT_NEAR(x.value(t), 5.0 + 2.0 * std::sin(w * t), 1e-14);
    EXPECT_NEAR(x.rate(t), 2.0 * w * std::cos(w * t), 1e-14);
    EXPECT_NEAR(x.acceleration(t), -2.0 * w * w * std::sin(w * t), 1e-14);
    EXPECT_EQ(z.value(t), -1.0);
    EXPECT_EQ(z.rate(t), 0.0);
  }
  EXPECT_DOUBLE_EQ(x.period(), 10.0);
}

}  // namespace
}  // namespace flexmoor::model
