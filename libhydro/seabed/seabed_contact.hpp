#pragma once
// Seabed contact per unit length of a line (MoorDyn v2's convention, docs/theory.md): where the point
// is below the bed by delta (measured along the bed's normal n; vertical on a flat bed), a
// spring-damper over the projected width d pushes it out,
//   N = (k_b delta - c_b u'.n) d,   f_n = N n      (k_b in Pa/m, c_b in Pa s/m)
// and friction opposes the velocity along the bed, v_t = u' - (u'.n) n, smoothly saturating at
// mu N:  f_t = -mu max(N, 0) v_t / sqrt(|v_t|^2 + v_s^2). The slip speed v_s sets how soft the
// law is near rest (MoorDyn's linear damper up to saturation has the same limits: zero at rest,
// mu N when sliding). Nothing acts above the bed.
// Derivatives treat the bed as locally plane (d delta / dx = -n).
#include <Eigen/Core>

#include "libhydro/seabed/bathymetry.hpp"

namespace flexmoor::hydro {

struct SeabedProperties {
  double stiffness = 3.0e6;  // k_b, Pa/m (MoorDyn's default kBot)
  double damping = 3.0e5;    // c_b, Pa s/m (MoorDyn's default cBot)
  double friction = 0.0;     // mu
  double slip_speed = 0.01;  // v_s, m/s
};

struct SeabedPointLoad {
  bool contact = false;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // per unit length
  Eigen::Matrix3d d_position = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();
};

// delta: penetration along n (> 0 in contact); n: the bed's upward unit normal; width: d.
SeabedPointLoad seabedLoad(const SeabedProperties& bed, double delta, const Eigen::Vector3d& n,
                           double width, const Eigen::Vector3d& u_dot);

// The same at a point `contact` (a line's integration point, a body's lowest point) over the
// bathymetry: the penetration along the normal of the bed's tangent plane under the point,
// n . ((x, y, z_b) - contact) = n_z (z_b - z), exact on a plane.
SeabedPointLoad seabedLoadAt(const Bathymetry& bathymetry, const SeabedProperties& bed,
                             const Eigen::Vector3d& contact, double width,
                             const Eigen::Vector3d& u_dot);

}  // namespace flexmoor::hydro
