#pragma once
// One displacement component of a point of a rigid body moving with a prescribed 6-dof motion
// about its reference point: translations surge, sway, heave (x, y, z) and rotations roll,
// pitch, yaw (about x, y, z), each a time function. The body's rotation is
// R = Rz(yaw) Ry(pitch) Rx(roll) (yaw, then pitch about the turned y, then roll about the twice
// turned x), so a point at `arm` from the reference point at t = 0 is at
// reference + translation(t) + R(t) arm, and
//   value(t) = offset + [translation(t) + R(t) arm - arm]_component,
// with its first and second time derivatives (the velocity v + omega x (R arm) and the
// acceleration of the point), exactly, by differentiating R's factors.
#include <Eigen/Dense>
#include <array>
#include <memory>

#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

class RigidPointMotion final : public TimeFunction {
 public:
  // motions: surge, sway, heave, roll, pitch, yaw; a null one stays at zero.
  RigidPointMotion(std::array<std::shared_ptr<const TimeFunction>, 6> motions,
                   const Eigen::Vector3d& arm, int component, double offset);
  double value(double t) const override;
  double rate(double t) const override;
  double acceleration(double t) const override;
  // The shortest period of the periodic motions (what a time step must resolve; 0 if none).
  double period() const override;

  // The point's displacement (order 0), velocity (1) or acceleration (2), without the offset.
  Eigen::Vector3d motion(double t, int order) const;

 private:
  double of(int dof, double t, int order) const;
  std::array<std::shared_ptr<const TimeFunction>, 6> motions_;
  Eigen::Vector3d arm_;
  int component_;
  double offset_;
};

}  // namespace flexmoor::model
