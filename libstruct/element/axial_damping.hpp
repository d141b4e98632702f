#pragma once
// Axial Kelvin-Voigt damping of a line (MoorDyn's BA): the axial force gains
// N_v = BA d(lambda)/dt, the rate of the engineering strain lambda - 1 with lambda = |y,1| / |x,1|:
//   d(lambda)/dt = (y,1 . v,1) / (|x,1| |y,1|),
// which on a straight two-node segment is MoorDyn's BA (dl/dt) / l0. Its virtual work
// int N_v d(lambda) ds0 gives the nodal forces f_I = int N_v L^I,1 t dxi, t = y,1 / |y,1|.
#include <Eigen/Core>
#include <cmath>

namespace flexmoor::element {

// The velocity gradient's part along the line, p = t t^T v,1 (so that N_v t = BA p / |x,1|), and
// its derivatives: dp/dv,1 = t t^T and dp/dy,1 = [t v,1^T + (t . v,1)(I - 2 t t^T)] / |y,1|.
struct AxialRate {
  Eigen::Vector3d value;
  Eigen::Matrix3d d_velocity, d_position;
};

inline AxialRate axialRate(const Eigen::Vector3d& y1, const Eigen::Vector3d& v1) {
  const double length = y1.norm();
  const Eigen::Vector3d t = y1 / length;
  const double rate = t.dot(v1);
  const Eigen::Matrix3d tt = t * t.transpose();
  return {rate * t, tt,
          (t * v1.transpose() + rate * (Eigen::Matrix3d::Identity() - 2.0 * tt)) / length};
}

// MoorDyn's negative BA input, a damping ratio zeta of the highest axial mode of a segment
// (omega = 2 sqrt(EA / m) / l_s, and a Kelvin-Voigt ratio BA omega / (2 EA)), turned into
// BA = zeta l_s sqrt(EA m), N s: l_s the unstretched segment length (MoorDyn's L / N), EA the
// axial stiffness and m the mass per unit length.
inline double dampingCoefficientOfRatio(double zeta, double segment_length, double EA, double m) {
  return zeta * segment_length * std::sqrt(EA * m);
}

}  // namespace flexmoor::element
