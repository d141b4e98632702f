#pragma once
// An analytic elastic catenary, written independently of libstruct, for verifying the cable
// statics.
//
// The cable: unstretched length L0, weight w per unit unstretched length, axial stiffness EA. Both
// ends are at the same height; the left end is pinned and the right end rides on a horizontal
// roller pulled by a horizontal force H. By symmetry each end carries the vertical reaction
// V = w L0 / 2. With s the unstretched arc length from the left end, the tension is
// T(s) = sqrt(H^2 + (V - w s)^2) and the geometry follows from
//   dx/ds = lambda(T) H / T,   dz/ds = -lambda(T) (V - w s) / T      (z up),
// where lambda(T) is the stretch the constitutive law gives to the tension T.
//
// Two laws are provided:
//  (a) Irvine's linear law, lambda = 1 + T / EA (Irvine, "Cable Structures", 1981, ch. 2, the
//      elastic catenary). Integrating the equations above with lambda = 1 + T / EA gives
//        x(s) = H s / EA + (H / w) [asinh(V / H) - asinh((V - w s) / H)]
//        z(s) = -(V s - w s^2 / 2) / EA - (1 / w) [sqrt(H^2 + V^2) - sqrt(H^2 + (V - w s)^2)]
//      so, at s = L0 and s = L0 / 2,
//        span = H L0 / EA + (2 H / w) asinh(V / H)
//        sag  = (sqrt(H^2 + V^2) - H) / w + w L0^2 / (8 EA)
//  (b) the law of flexmoor's LinearElasticCable (docs/theory.md#cable-laws, Eq. 2.53): second Piola
//      S = E (lambda^2 - 1) / 2, so the force is T = EA lambda (lambda^2 - 1) / 2; lambda(T) is the
//      root of that cubic (Newton) and the geometry is integrated numerically with GSL's adaptive
//      quadrature (gsl_integration_qags, epsabs 0, epsrel 1e-12).
#include <functional>

namespace flexmoor::test {

struct CatenaryInputs {
  double unstretched_length = 0.0;  // L0
  double weight = 0.0;              // w, per unit unstretched length
  double axial_stiffness = 0.0;     // EA
  double horizontal_force = 0.0;    // H
  double verticalReaction() const { return 0.5 * weight * unstretched_length; }
};

struct CatenaryShape {
  double span = 0.0;              // horizontal distance between the supports
  double centre_sag = 0.0;        // depth of the mid-length point below the supports
  double support_movement = 0.0;  // L0 - span, how far the roller moved from the straight cable
};

// Law (a): Irvine's closed form.
CatenaryShape irvineCatenary(const CatenaryInputs& in);

// Law (b): S = E (lambda^2 - 1) / 2, integrated along the unstretched arc length.
CatenaryShape greenStrainCatenary(const CatenaryInputs& in);

// Any law given as stretch(T): the geometry integrals above by adaptive quadrature.
CatenaryShape integrateCatenary(const CatenaryInputs& in,
                                const std::function<double(double)>& stretch);

// The inextensible catenary (EA -> infinity): span = (2 H / w) asinh(V / H),
// sag = (sqrt(H^2 + V^2) - H) / w.
CatenaryShape inextensibleCatenary(const CatenaryInputs& in);

// Law (b) forwards and backwards: T = EA lambda (lambda^2 - 1) / 2, and the stretch lambda >= 1
// that carries a tension T >= 0 (Newton on the cubic from lambda = 1 + T / EA, which lies on the
// convex side of the root, so the iterates decrease monotonically to it).
double greenStrainTension(double stretch, double EA);
double greenStrainStretch(double tension, double EA);

}  // namespace flexmoor::test
