#pragma once
// The friction of the seabed on a line or a body in contact (seabed_contact.hpp), along the bed's
// plane against the tangential velocity v_t = (I - n n^T) u', from the contact's normal force N,
// by one of two laws:
//
//   coulomb  flexmoor's `friction: mu`: Coulomb's law with a smooth start,
//              f = -mu max(N, 0) v_t / sqrt(|v_t|^2 + v_s^2),
//            zero at rest, mu N once sliding well above the slip speed v_s; smooth everywhere.
//   moordyn  MoorDyn-C v2's FrictionCoefficient mu, FricDamp c and StatDynFricScale s (the bottom
//            contact of Line::getStateDeriv, source/Line.cpp; docs/inputs.rst): a linear damper
//            on the sliding speed, saturated at Coulomb's force,
//              F = mu c |v_t|,  F = mu |N| where F > s mu |N|,   f = -F v_t / |v_t|  (0 at rest),
//            c the friction damping (N s/m at one of MoorDyn's nodes; default 200), s the ratio
//            of static to dynamic friction (default 1). Below the saturation speed
//            s |N| / c the friction does not depend on N at all; with s > 1 the damper's force
//            rises to s mu |N| and drops to mu |N| beyond (MoorDyn's law as written: a jump).
//
// Each returns its force and its derivatives in u' and N (the caller chains N's own in position
// and velocity); the tangent of the moordyn law is each branch's own, the damper's
// -mu c (I - n n^T) at rest.
#include <Eigen/Core>

namespace flexmoor::hydro {

struct FrictionForce {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d d_normal = Eigen::Vector3d::Zero();    // df/dN
  Eigen::Matrix3d d_velocity = Eigen::Matrix3d::Zero();  // df/du' at fixed N
};

// n: the bed's upward unit normal; u_dot: the point's velocity.
FrictionForce coulombFriction(double mu, double slip_speed, double N, const Eigen::Vector3d& n,
                              const Eigen::Vector3d& u_dot);

// damping: c in the force's measure (a line's per unit length: MoorDyn's FricDamp over its node
// length; a body's: FricDamp itself); scale: s.
FrictionForce moordynFriction(double mu, double damping, double scale, double N,
                              const Eigen::Vector3d& n, const Eigen::Vector3d& u_dot);

}  // namespace flexmoor::hydro
