#include "libhydro/seabed/seabed_friction.hpp"

#include <cmath>

namespace flexmoor::hydro {

using Eigen::Matrix3d;
using Eigen::Vector3d;

FrictionForce coulombFriction(double mu, double slip_speed, double N, const Vector3d& n,
                              const Vector3d& u_dot) {
  FrictionForce out;
  if (!(mu > 0.0) || !(N > 0.0)) return out;
  const Matrix3d tangential = Matrix3d::Identity() - n * n.transpose();
  const Vector3d vt = tangential * u_dot;
  const double s = std::sqrt(vt.squaredNorm() + slip_speed * slip_speed);
  const Vector3d phi = vt / s;  // |phi| < 1, -> v_t / |v_t| when sliding
  const Matrix3d dphi = (Matrix3d::Identity() / s - vt * vt.transpose() / (s * s * s)) * tangential;
  out.force = -mu * N * phi;
  out.d_normal = -mu * phi;
  out.d_velocity = -mu * N * dphi;
  return out;
}

FrictionForce moordynFriction(double mu, double damping, double scale, double N, const Vector3d& n,
                              const Vector3d& u_dot) {
  FrictionForce out;
  if (!(mu > 0.0)) return out;
  const Matrix3d tangential = Matrix3d::Identity() - n * n.transpose();
  const Vector3d vt = tangential * u_dot;
  const double speed = vt.norm(), cap = mu * std::abs(N);
  if (mu * damping * speed <= scale * cap) {  // the damper (at rest too: f = 0, its tangent)
    out.force = -mu * damping * vt;
    out.d_velocity = -mu * damping * tangential;
    return out;
  }
  // Saturated: mu |N| against the motion (speed > 0 here, since scale * cap >= 0).
  const Vector3d direction = vt / speed;
  out.force = -cap * direction;
  out.d_normal = -mu * (N < 0.0 ? -1.0 : 1.0) * direction;
  out.d_velocity = -cap *
                   (Matrix3d::Identity() / speed - vt * vt.transpose() / (speed * speed * speed)) *
                   tangential;
  return out;
}

}  // namespace flexmoor::hydro
