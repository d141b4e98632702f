#include "libhydro/seabed/seabed_contact.hpp"

#include <cmath>
#include <limits>

#include "libhydro/seabed/seabed_friction.hpp"

namespace flexmoor::hydro {

SeabedPointLoad seabedLoad(const SeabedProperties& bed, double delta, const Eigen::Vector3d& n,
                           double width, const Eigen::Vector3d& u_dot, double node_length) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  SeabedPointLoad out;
  // On the bed (delta = 0) the force is zero but the contact's stiffness is there: a line laid
  // exactly on the bed (a catenary start) is held by it from the first Newton iteration.
  if (!(delta >= 0.0)) return out;
  out.contact = true;
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
  const FrictionForce f = bed.friction_law == FrictionLaw::MoorDyn
                              ? moordynFriction(bed.friction, bed.friction_damping / node_length,
                                                bed.static_dynamic_scale, N, n, u_dot)
                              : coulombFriction(bed.friction, bed.slip_speed, N, n, u_dot);
  out.force += f.force;
  out.d_position += f.d_normal * dN_dx.transpose();
  out.d_velocity += f.d_normal * dN_dv.transpose() + f.d_velocity;
  return out;
}

SeabedPointLoad seabedLoadAt(const Bathymetry& bathymetry, const SeabedProperties& bed,
                             const Eigen::Vector3d& contact, double width,
                             const Eigen::Vector3d& u_dot, double node_length) {
  const double x = contact.x(), y = contact.y();
  const Eigen::Vector3d n = bathymetry.normal(x, y);
  const double height = bathymetry.height(x, y);
  double delta = n.z() * (height - contact.z());
  // A point on the bed to round-off is on it: an integration point of a line laid exactly on the
  // bed (a catenary start) is interpolated from its nodes' heights, sum N_i z_i, within a few
  // eps |z| of the bed, above or below it by chance; above it, the point would have no contact
  // stiffness, and a node whose points all fell there had none in the first Newton solve (a
  // fully laid chain's node driven 70 km down).
  const double roundoff = 64.0 * std::numeric_limits<double>::epsilon() *
                          (std::abs(height) + std::abs(contact.z()));
  if (delta < 0.0 && delta >= -roundoff) delta = 0.0;
  return seabedLoad(bed, delta, n, width, u_dot, node_length);
}

}  // namespace flexmoor::hydro
