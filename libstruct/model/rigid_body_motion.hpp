#pragma once
// The prescribed 6-dof motion of a rigid body about its reference point: translations surge,
// sway, heave (x, y, z) and rotations roll, pitch, yaw (about x, y, z), each a time function.
// The body's rotation is R = Rz(yaw) Ry(pitch) Rx(roll) (yaw, then pitch about the turned y,
// then roll about the twice turned x), so a point at `arm` from the reference point at t = 0 is
// at reference + translation(t) + R(t) arm. One motion is shared by every point the body carries
// (rigid_point_motion.hpp), so that a host program that drives the body (coupled_motion.hpp)
// moves them all.
#include <Eigen/Dense>
#include <array>
#include <memory>

#include "libstruct/model/time_function.hpp"

namespace flexmoor::model {

class RigidBodyMotion {
 public:
  // surge, sway, heave, roll, pitch, yaw; a null one stays at zero.
  using Dofs = std::array<std::shared_ptr<const TimeFunction>, 6>;
  explicit RigidBodyMotion(Dofs dofs) : dofs_(std::move(dofs)) {}

  // The displacement (order 0), velocity (1) or acceleration (2) of the point at `arm`:
  // translation + (R - I) arm and its first and second time derivatives, exactly, by
  // differentiating R's factors (v + omega x (R arm) for the velocity).
  Eigen::Vector3d pointMotion(const Eigen::Vector3d& arm, double t, int order) const;
  // Dof `dof` (0-5 as in Dofs) at t: its value, rate or acceleration (order 0, 1, 2).
  double dof(int dof, double t, int order) const;
  // The shortest period of the periodic motions (what a time step must resolve; 0 if none).
  double period() const;

  const Dofs& dofs() const { return dofs_; }
  // Puts `f` in place of dof `dof`'s motion: a host program takes the body over.
  void drive(int dof, std::shared_ptr<const TimeFunction> f) { dofs_[dof] = std::move(f); }

 private:
  Dofs dofs_;
};

}  // namespace flexmoor::model
