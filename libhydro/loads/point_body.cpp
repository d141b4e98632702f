#include "libhydro/loads/point_body.hpp"

#include <algorithm>
#include <cmath>

#include "libhydro/loads/quadratic_drag.hpp"

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

}  // namespace

PointBody PointBody::sphere(double diameter, double cd, double ca) {
  PointBody b;
  b.diameter = diameter;
  b.volume = kPi * diameter * diameter * diameter / 6.0;
  b.drag_area = cd * 0.25 * kPi * diameter * diameter;
  b.added_mass = ca;
  return b;
}

SubmergedVolume submergedVolume(const PointBody& b, double depth) {
  if (!(b.diameter > 0.0)) return {depth >= 0.0 ? b.volume : 0.0, 0.0};
  const double r = 0.5 * b.diameter, s = std::clamp(r + depth, 0.0, 2.0 * r);
  // V(s) = pi s^2 (3 r - s) / 3; dV/ds = pi s (2 r - s), the waterplane circle's area.
  const bool inside = r + depth > 0.0 && r + depth < 2.0 * r;
  return {kPi * s * s * (3.0 * r - s) / 3.0, inside ? kPi * s * (2.0 * r - s) : 0.0};
}

PointBodyLoad pointBodyLoad(const PointBody& b, double rho, double g, double depth,
                            const Eigen::Vector3d& u_dot, const Eigen::Vector3d& u_ddot,
                            const Eigen::Vector3d& v, const Eigen::Vector3d& a) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const SubmergedVolume w = submergedVolume(b, depth);
  const double wet = b.volume > 0.0 ? w.volume / b.volume : 0.0;
  const double d_wet = b.volume > 0.0 ? w.d_elevation / b.volume : 0.0;
  const Vector3d vr = v - u_dot;
  const Vector3d drag = 0.5 * rho * b.drag_area * quadraticDrag(vr);
  const Vector3d inertia = rho * b.volume * ((1.0 + b.added_mass) * a - b.added_mass * u_ddot);
  const Vector3d buoyancy = rho * g * b.volume * Vector3d::UnitZ();
  PointBodyLoad out;
  out.force = wet * (buoyancy + drag + inertia);
  const Matrix3d d_vr = wet * 0.5 * rho * b.drag_area * quadraticDragDerivative(vr);
  out.d_fluid_velocity = d_vr;
  out.d_velocity = -d_vr;
  out.d_fluid_acceleration = wet * rho * b.volume * (1.0 + b.added_mass) * Matrix3d::Identity();
  out.d_acceleration = -wet * rho * b.volume * b.added_mass * Matrix3d::Identity();
  out.d_depth = d_wet * (buoyancy + drag + inertia);
  return out;
}

}  // namespace flexmoor::hydro
