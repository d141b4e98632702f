#pragma once
// One displacement component of a point carried by a rigid body in prescribed motion
// (rigid_body_motion.hpp): the point at `arm` from the body's reference point at t = 0 has
//   value(t) = offset + [translation(t) + R(t) arm - arm]_component,
// with its first and second time derivatives (the velocity v + omega x (R arm) and the
// acceleration of the point), exactly.
#include <Eigen/Dense>
#include <array>
#include <memory>

#include "libstruct/model/rigid_body_motion.hpp"
#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

class RigidPointMotion final : public TimeFunction {
 public:
  // A point of `body`, which it shares with the body's other points.
  RigidPointMotion(std::shared_ptr<const RigidBodyMotion> body, const Eigen::Vector3d& arm,
                   int component, double offset);
  // A point of a body of its own moving by `motions` (surge, sway, heave, roll, pitch, yaw; a
  // null one stays at zero).
  RigidPointMotion(RigidBodyMotion::Dofs motions, const Eigen::Vector3d& arm, int component,
                   double offset);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;
  // The shortest period of the body's periodic motions (0 if none).
  double period() const override { return body_->period(); }

  // The point's displacement (order 0), velocity (1) or acceleration (2), without the offset.
  Eigen::Vector3d motion(double t, int order) const { return body_->pointMotion(arm_, t, order); }
  const RigidBodyMotion& body() const { return *body_; }
  const Eigen::Vector3d& arm() const { return arm_; }

 private:
  std::shared_ptr<const RigidBodyMotion> body_;
  Eigen::Vector3d arm_;
  int component_;
  double offset_;
};

}  // namespace flexmoor::model
