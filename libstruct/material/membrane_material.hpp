#pragma once
// Constitutive laws of a membrane in convected coordinates, behind one interface (Eq. 2.40-2.42,
// Appendix B).
//
// A law takes the covariant metrics of a material point, reference a_ab = x,a . x,b and current
// A_ab = y,a . y,b (symmetric positive definite), with the Green strain
// gamma_ab = (A_ab - a_ab) / 2 (Eq. 2.14). It returns the contravariant Kirchhoff stress T^ab
// (second Piola-Kirchhoff, force per unit reference area, Eq. 2.19) and the tangent
// C^ablm = dT^ab / dgamma_lm, symmetric in a-b, in l-m and between the pairs.
//
// Voigt notation, over the index pairs (11, 22, 12):
//   stress [T^11, T^22, T^12],   strain [gamma_11, gamma_22, 2 gamma_12] (engineering shear),
//   C(p, q) = C^{ab lm} with ab the p-th pair and lm the q-th, no entry scaled.
// The factor 2 of the shear strain stands for the two equal terms C^ab12 dgamma_12 and
// C^ab21 dgamma_21 of the contraction, so dT = C * [dgamma_11, dgamma_22, 2 dgamma_12]: column 2
// is dT/dA_12 (A_12 = A_21 moved together) and columns 0, 1 are 2 dT/dA_11, 2 dT/dA_22. In the
// element (Eq. 4.39), with B the rows d(gamma_11, gamma_22, 2 gamma_12)/du, i.e. M^I,1 y,1,
// M^I,2 y,2 and M^I,1 y,2 + M^I,2 y,1, the material stiffness is B^T C B h0 sqrt(a).
#include <Eigen/Core>
#include <string>

namespace flexmoor::material {

struct MembraneStress {
  Eigen::Matrix2d T;  // T^ab, symmetric
  Eigen::Matrix3d C;  // dT^ab / dgamma_lm in the Voigt notation above, symmetric
};

class MembraneMaterial {
 public:
  virtual ~MembraneMaterial() = default;

  // Stress and tangent for reference metric a and current metric A.
  virtual MembraneStress stress(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const = 0;

  // Strain energy W per unit reference volume; T^ab = dW/dgamma_ab = 2 dW/dA_ab.
  virtual double strainEnergyDensity(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const = 0;

  virtual std::string name() const = 0;
};

// Square of the thickness stretch of an incompressible membrane, l2 = a / A with a = det(a_ab),
// A = det(A_ab) (Eq. 2.42); the current thickness is h0 sqrt(l2).
double thicknessStretchSquared(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A);

// Eq. 2.40-2.41, isotropic linear elasticity in plane stress, written on the Green strain:
// C^ablm = E / (2 (1 + nu)) [a^al a^bm + a^am a^bl + 2 nu / (1 - nu) a^ab a^lm],
// T^ab = C^ablm gamma_lm, W = T^ab gamma_ab / 2. Valid for -1 < nu < 1.
class LinearElasticPlaneStress final : public MembraneMaterial {
 public:
  LinearElasticPlaneStress(double youngs_modulus, double poisson_ratio);
  MembraneStress stress(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const override;
  double strainEnergyDensity(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const override;
  std::string name() const override { return "linear_elastic"; }

 private:
  double E_, nu_;
};

// Eq. 2.42, incompressible Mooney-Rivlin in plane stress, W = C1 (I1 - 3) + C2 (I2 - 3) with
// the thickness stretch eliminated by incompressibility: I1 = I_A + l2, I2 = A / a + l2 I_A,
// I_A = a^ab A_ab. T^ab = 2 a^ab (C1 + C2 l2) + 2 A^ab J, J = C2 A / a - l2 (C1 + C2 I_A);
// the tangent is that of Appendix B. At small strain it is the plane-stress law with
// E = 6 (C1 + C2), nu = 1/2.
class MooneyRivlinMembrane final : public MembraneMaterial {
 public:
  MooneyRivlinMembrane(double C1, double C2);
  MembraneStress stress(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const override;
  double strainEnergyDensity(const Eigen::Matrix2d& a, const Eigen::Matrix2d& A) const override;
  std::string name() const override { return "mooney_rivlin"; }

 private:
  double C1_, C2_;
};

}  // namespace flexmoor::material
