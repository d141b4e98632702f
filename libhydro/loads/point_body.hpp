#pragma once
// The hydrodynamic load on a point body (a buoy or a clump weight; docs/theory.md#point-bodies):
//   f = rho g V_w e_z + 1/2 rho CdA |v_r| v_r + rho V (1 + Ca) a - rho V Ca u''
// with V_w its submerged volume (a sphere's cap below the local surface), v_r = v - u'. Inertia
// and drag act on the submerged part only: V and CdA are scaled by the wetted fraction V_w / V.
#include <Eigen/Core>

namespace flexmoor::hydro {

struct PointBody {
  double volume = 0.0;      // V
  double drag_area = 0.0;   // CdA: drag coefficient times projected area
  double added_mass = 0.0;  // Ca
  double diameter = 0.0;    // > 0: a sphere, whose submerged volume is a spherical cap
  static PointBody sphere(double diameter, double cd, double ca = 0.5);
};

struct SubmergedVolume {
  double volume = 0.0;
  double d_elevation = 0.0;  // dV_w / d(eta - z_c): the waterplane area
};

// The submerged volume of `b` with its centre `depth` = eta - z_c below the surface: a sphere's
// cap pi s^2 (3 R - s) / 3 with s = clamp(R + depth, 0, 2 R); other bodies all or nothing.
SubmergedVolume submergedVolume(const PointBody& b, double depth);

struct PointBodyLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();      // df/du'
  Eigen::Matrix3d d_acceleration = Eigen::Matrix3d::Zero();  // df/du'' (= -rho V_w Ca I)
  Eigen::Vector3d d_depth = Eigen::Vector3d::Zero();         // df/d(eta - z_c)
  Eigen::Matrix3d d_fluid_velocity = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d d_fluid_acceleration = Eigen::Matrix3d::Zero();
};

PointBodyLoad pointBodyLoad(const PointBody& b, double rho, double g, double depth,
                            const Eigen::Vector3d& u_dot, const Eigen::Vector3d& u_ddot,
                            const Eigen::Vector3d& v, const Eigen::Vector3d& a);

}  // namespace flexmoor::hydro
