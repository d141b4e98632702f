#include "libstruct/model/rigid_body_motion.hpp"

#include <algorithm>
#include <cmath>

namespace flexmoor::model {
namespace {

// The rotation by angle a about axis i, and its first and second derivatives in a.
struct AxisRotation {
  Eigen::Matrix3d r, dr, ddr;
};

AxisRotation axisRotation(int i, double a) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double c = std::cos(a), s = std::sin(a);
  AxisRotation m{Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  m.r(i, i) = 1.0;
  m.r(j, j) = c, m.r(j, k) = -s, m.r(k, j) = s, m.r(k, k) = c;
  m.dr(j, j) = -s, m.dr(j, k) = -c, m.dr(k, j) = c, m.dr(k, k) = -s;
  m.ddr = -m.r;
  m.ddr(i, i) = 0.0;
  return m;
}

}  // namespace

double RigidBodyMotion::dof(int dof, double t, int order) const {
  const TimeFunction* f = dofs_[dof].get();
  if (!f) return 0.0;
  return order == 0 ? f->value(t) : order == 1 ? f->rate(t) : f->acceleration(t);
}

Eigen::Vector3d RigidBodyMotion::pointMotion(const Eigen::Vector3d& arm, double t,
                                             int order) const {
  Eigen::Vector3d translation(dof(0, t, order), dof(1, t, order), dof(2, t, order));
  // R = A B C with A = Rz(yaw), B = Ry(pitch), C = Rx(roll); each factor's time derivatives
  // from its angle's: dR/dt = a' R_a, d2R/dt2 = a'' R_a + a'^2 R_aa.
  std::array<Eigen::Matrix3d, 3> f0, f1, f2;  // factors A, B, C and their derivatives
  const int axis[3] = {2, 1, 0}, angle[3] = {5, 4, 3};
  for (int n = 0; n < 3; ++n) {
    const AxisRotation m = axisRotation(axis[n], dof(angle[n], t, 0));
    const double rate = dof(angle[n], t, 1), acc = dof(angle[n], t, 2);
    f0[n] = m.r;
    f1[n] = rate * m.dr;
    f2[n] = acc * m.dr + rate * rate * m.ddr;
  }
  Eigen::Matrix3d r;
  if (order == 0) {
    r = f0[0] * f0[1] * f0[2] - Eigen::Matrix3d::Identity();
  } else if (order == 1) {
    r = f1[0] * f0[1] * f0[2] + f0[0] * f1[1] * f0[2] + f0[0] * f0[1] * f1[2];
  } else {
    r = f2[0] * f0[1] * f0[2] + f0[0] * f2[1] * f0[2] + f0[0] * f0[1] * f2[2] +
        2.0 * (f1[0] * f1[1] * f0[2] + f1[0] * f0[1] * f1[2] + f0[0] * f1[1] * f1[2]);
  }
  return translation + r * arm;
}

double RigidBodyMotion::period() const {
  double shortest = 0.0;
  for (const auto& f : dofs_)
    if (f && f->period() > 0.0)
      shortest = shortest > 0.0 ? std::min(shortest, f->period()) : f->period();
  return shortest;
}

}  // namespace flexmoor::model
