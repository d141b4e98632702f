#include "libhydro/seabed/seabed_contact.hpp"

#include <cmath>

namespace flexmoor::hydro {

SeabedPointLoad seabedLoad(const SeabedProperties& bed, double delta, const Eigen::Vector3d& n,
                           double width, const Eigen::Vector3d& u_dot) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  SeabedPointLoad out;
  // On the bed (delta = 0) the force is zero but the contact's stiffness is there: a line laid
  // exactly on the bed (a catenary start) is held by it from the first Newton iteration.
  if (!(delta >= 0.0)) return out;
  out.contact = true;
  const Matrix3d nn = n * n.transpose();
  // The damping's share phi rises linearly over the first kDampingDepth d of penetration.
  const double depth = kDampingDepth * width;
  const double phi = delta < depth ? delta / depth : 1.0, dphi = delta < depth ? 1.0 / depth : 0.0;
  const double vn = u_dot.dot(n);
  const double N = (bed.stiffness * delta - bed.damping * phi * vn) * width;
  // dN/dx = (-k_b + c_b v_n phi') d n (d delta / dx = -n), dN/du' = -c_b phi d n.
  const Vector3d dN_dx = (-bed.stiffness + bed.damping * vn * dphi) * width * n,
                 dN_dv = -bed.damping * phi * width * n;
  out.force = N * n;
  out.d_position = n * dN_dx.transpose();
  out.d_velocity = n * dN_dv.transpose();
  if (bed.friction > 0.0 && N > 0.0) {
    const Vector3d vt = u_dot - u_dot.dot(n) * n;
    const double s = std::sqrt(vt.squaredNorm() + bed.slip_speed * bed.slip_speed);
    const Vector3d phi = vt / s;  // |phi| < 1, -> v_t / |v_t| when sliding
    const Matrix3d dphi = (Matrix3d::Identity() / s - vt * vt.transpose() / (s * s * s)) *
                          (Matrix3d::Identity() - nn);
    out.force -= bed.friction * N * phi;
    out.d_position -= bed.friction * phi * dN_dx.transpose();
    out.d_velocity -= bed.friction * (phi * dN_dv.transpose() + N * dphi);
  }
  return out;
}

SeabedPointLoad seabedLoadAt(const Bathymetry& bathymetry, const SeabedProperties& bed,
                             const Eigen::Vector3d& contact, double width,
                             const Eigen::Vector3d& u_dot) {
  const double x = contact.x(), y = contact.y();
  const Eigen::Vector3d n = bathymetry.normal(x, y);
  const double delta = n.z() * (bathymetry.height(x, y) - contact.z());
  return seabedLoad(bed, delta, n, width, u_dot);
}

}  // namespace flexmoor::hydro
