#pragma once
// Seabed contact per unit length of a line (MoorDyn v2's convention, docs/theory.md): where the
// point is below the bed by delta (measured along the bed's normal n; vertical on a flat bed), a
// spring-damper over the projected width d pushes it out,
//   N = (k_b delta - phi c_b u'.n) d,   f_n = N n      (k_b in Pa/m, c_b in Pa s/m)
// where the damping's share phi = min(1, delta / (kDampingDepth d)) makes the force continuous as
// a point touches down (MoorDyn's full c_b from delta = 0 on makes it jump by c_b |u'.n| d, which
// no Newton iteration can converge across: a chain landing at 0.5 m/s jumps by 15 kN/m). Over
// the ramp the damping adds c_b |u'.n| / (kDampingDepth d) to the contact's stiffness; at 10% of
// the diameter that stays of the order of k_b at the speeds a line lands with (OC4's chain at
// 0.2 m/s: 7.8e6 against 3e6 Pa/m), where at 1% it was 26 times k_b and a time step of 0.4 s
// cycled about the ramp's end until it was cut. Beyond the ramp it is MoorDyn's law (the
// Hunt-Crossley idea of a damping that grows with the penetration); it matters only while a point
// moves across the bed's normal, and a line resting on the bed is carried by the spring alone.
// Friction opposes the velocity along the bed, v_t = u' - (u'.n) n, by one of two laws
// (seabed_friction.hpp): flexmoor's Coulomb law with a smooth start, f_t = -mu max(N, 0) v_t /
// sqrt(|v_t|^2 + v_s^2), mu N as soon as the line slides faster than the slip speed v_s; or
// MoorDyn's, whose FrictionCoefficient acts through its friction damping FricDamp: a viscous drag
// mu FricDamp |v_t| that saturates at mu |N| only above |N| / FricDamp (per node: 166 m/s for a
// 390 kg/m chain in 10 m segments at the default 200 N s/m, so in practice a weak drag). The two
// are different laws, alike only when the line slides well above both speeds (docs/theory.md).
// Nothing acts above the bed.
// Derivatives treat the bed as locally plane (d delta / dx = -n).
#include <Eigen/Core>

#include "libhydro/seabed/bathymetry.hpp"

namespace flexmoor::hydro {

// The penetration, as a fraction of the line's width, over which the bed's damping comes in.
inline constexpr double kDampingDepth = 0.1;

enum class FrictionLaw { Coulomb, MoorDyn };

struct SeabedProperties {
  double stiffness = 3.0e6;  // k_b, Pa/m (MoorDyn's default kBot)
  double damping = 3.0e5;    // c_b, Pa s/m (MoorDyn's default cBot)
  double friction = 0.0;     // mu, by the friction law (seabed_friction.hpp)
  double slip_speed = 0.01;  // v_s, m/s (coulomb)
  FrictionLaw friction_law = FrictionLaw::Coulomb;
  double friction_damping = 200.0;    // c, N s/m at a node (moordyn: MoorDyn's FricDamp)
  double static_dynamic_scale = 1.0;  // s (moordyn: MoorDyn's StatDynFricScale)
};

struct SeabedPointLoad {
  bool contact = false;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // per unit length
  Eigen::Matrix3d d_position = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();
};

// delta: penetration along n (> 0 in contact); n: the bed's upward unit normal; width: d.
// node_length: the length over which the moordyn law spreads a node's friction damping (a line's
// node spacing, MoorDyn's segment length, for a force per unit length: c / node_length); 1 for a
// body (the force itself: c).
SeabedPointLoad seabedLoad(const SeabedProperties& bed, double delta, const Eigen::Vector3d& n,
                           double width, const Eigen::Vector3d& u_dot, double node_length = 1.0);

// The same at a point `contact` (a line's integration point, a body's lowest point) over the
// bathymetry: the penetration along the normal of the bed's tangent plane under the point,
// n . ((x, y, z_b) - contact) = n_z (z_b - z), exact on a plane.
SeabedPointLoad seabedLoadAt(const Bathymetry& bathymetry, const SeabedProperties& bed,
                             const Eigen::Vector3d& contact, double width,
                             const Eigen::Vector3d& u_dot, double node_length = 1.0);

}  // namespace flexmoor::hydro
