#include "libhydro/loads/morison.hpp"

#include <cmath>

#include "libhydro/loads/quadratic_drag.hpp"

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

}  // namespace

Eigen::Matrix3d addedMassPerLength(const MorisonCoefficients& c, double rho,
                                   const Eigen::Vector3d& t) {
  const double area = 0.25 * kPi * c.diameter * c.diameter;
  const Eigen::Matrix3d tt = t * t.transpose();
  return rho * area * (c.ca * (Eigen::Matrix3d::Identity() - tt) + c.ca_axial * tt);
}

MorisonPointLoad morisonLoad(const MorisonCoefficients& c, double rho, const Eigen::Vector3d& t,
                             const Eigen::Vector3d& u_dot, const Eigen::Vector3d& u_ddot,
                             const Eigen::Vector3d& v, const Eigen::Vector3d& a) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const Matrix3d I = Matrix3d::Identity(), tt = t * t.transpose(), normal = I - tt;
  const double area = 0.25 * kPi * c.diameter * c.diameter;
  const double tangential_width =
      c.tangential_area == MorisonCoefficients::TangentialDragArea::Perimeter ? kPi * c.diameter
                                                                              : c.diameter;
  const double kn = 0.5 * rho * c.diameter * c.cn, kt = 0.5 * rho * tangential_width * c.ct;

  // Relative velocity and its split (Eq. E.5-E.7): v_rt = (v_r . t) t, v_rn = v_r - v_rt.
  const Vector3d vr = v - u_dot;
  const double vr_t = vr.dot(t);
  const Vector3d vrt = vr_t * t, vrn = vr - vrt;
  const Matrix3d Dn = quadraticDragDerivative(vrn), Dt = quadraticDragDerivative(vrt);
  // d v_rt / d t = (v_r . t) I + t v_r^T; d v_rn / d t = -(that).
  const Matrix3d dvrt_dt = vr_t * I + t * vr.transpose();

  MorisonPointLoad out;
  const Matrix3d fluid_inertia = rho * area * ((1.0 + c.ca) * normal + (1.0 + c.ca_axial) * tt);
  const Matrix3d added = addedMassPerLength(c, rho, t);
  out.force =
      kn * quadraticDrag(vrn) + kt * quadraticDrag(vrt) + fluid_inertia * a - added * u_ddot;

  // Drag: d f / d v_r = kn Dn (I - t t^T) + kt Dt t t^T.
  const Matrix3d d_vr = kn * Dn * normal + kt * Dt * tt;
  out.d_fluid_velocity = d_vr;
  out.d_velocity = -d_vr;
  out.d_fluid_acceleration = fluid_inertia;
  out.d_acceleration = -added;
  // Tangent: the drag split, and the projections of a and u'' (d (tt^T w) / dt = (t.w) I + t w^T).
  const auto dProjection = [&](const Vector3d& w) { return t.dot(w) * I + t * w.transpose(); };
  out.d_tangent = (kt * Dt - kn * Dn) * dvrt_dt +
                  rho * area * (c.ca_axial - c.ca) * (dProjection(a) - dProjection(u_ddot));
  return out;
}

}  // namespace flexmoor::hydro
