#pragma once
// The cable-reinforced Mooney-Rivlin tube of the dissertation's Example 5 solved without finite
// elements: a shooting solution of the equilibrium equations of the axisymmetric membrane,
// written from the strain energy, independent of libstruct (no element, material, load or solver
// code of flexmoor is used).
//
// Every material point keeps its axial coordinate Z (longitudinal motion restrained, as in
// Example 3), so the deformed meridian is r(Z), with the stretches
//   lambda1 = sqrt(1 + s^2), s = dr/dZ (meridian),    lambda2 = r / R (hoop).
// The incompressible Mooney-Rivlin membrane stores h0 W per unit reference area,
//   W = C1 (I1 - 3) + C2 (I2 - 3),  I1 = l1^2 + l2^2 + l1^-2 l2^-2,  I2 = l1^-2 + l2^-2 + l1^2 l2^2,
// i.e. E(r, s) = R h0 W per radian and unit length of Z. A follower pressure p on the current
// surface pushes outwards by p r per radian and unit Z (its axial part is carried by the axial
// restraint). A hoop cable of reference area A at Z_c (the Mooney-Rivlin cable law, Eq. 2.54)
// stores R A Wc(lambda), Wc = C1c (l^2 + 2 / l - 3) + C2c (2 l + l^-2 - 3), lambda = r / R, and
// pulls inwards by A dWc/dlambda = A lambda S, S = 2 (1 - l^-3)(C1c + C2c / l), per radian.
// Stationary total potential energy gives, with the meridional force per radian
//   q = dE/ds = 2 R h0 s (1 - l1^-4 l2^-2)(C1 + C2 l2^2):
//   dq/dZ = dE/dr - p r = 2 h0 (l2 - l2^-3 l1^-2)(C1 + C2 l1^2) - p r    between cables,
//   q(Zc+) - q(Zc-) = A lambda S(lambda)                                   at a cable,
//   q(0) = A_0 lambda S at the free end Z = 0 (a cable of area A_0 there, or none: q = 0),
//   q(L) = -A_L lambda S at a symmetry plane Z = L (the cable cut by it: half its area).
// Between cables the system is integrated in (r, s), with ds/dZ = (dq/dZ - dq/dr s) / (dq/ds), by
// GSL's rk8pd (relative tolerance 1e-12); r(0) is shot for with Brent (findRoot) until the
// symmetry-plane condition holds.
#include <vector>

namespace flexmoor::test {

struct HoopRing {
  double z = 0.0;     // reference axial position
  double area = 0.0;  // reference cross-section A (half the cable's at a symmetry plane)
};

struct ReinforcedTubeInputs {
  double radius = 10.0, thickness = 0.01;  // R, h0
  double C1 = 2300.0, C2 = 280.0;          // the membrane
  double cable_C1 = 14000.0, cable_C2 = 4000.0;
  double length = 15.0;  // from the free end Z = 0 to the symmetry plane Z = L
  std::vector<HoopRing> rings;
  double pressure = 4.0;
};

// The membrane's meridional law in the variables of the shooting solution, exposed for the
// self-checks of the reference (finite differences of the energy).
struct TubeMembraneLaw {
  double R, h0, C1, C2;
  double energy(double r, double s) const;           // E(r, s) = R h0 W, from the invariants
  double meridionalForce(double r, double s) const;  // q = dE/ds
  double dForceDSlope(double r, double s) const;     // dq/ds
  double dForceDRadius(double r, double s) const;    // dq/dr
  double hoopForce(double r, double s) const;        // dE/dr
};

// The hoop cable: energy R A Wc(r / R) per radian and its derivative A lambda S.
struct HoopRingLaw {
  double R, C1, C2;
  double energy(double r, double area) const;
  double inwardForce(double r, double area) const;
};

// The radial displacements r(Z) - R at the points `z` (each in [0, L]).
std::vector<double> reinforcedTubeDisplacements(const ReinforcedTubeInputs& in,
                                                const std::vector<double>& z);

}  // namespace flexmoor::test
