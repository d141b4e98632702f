#include "libstruct/material/membrane_material.hpp"

#include <Eigen/LU>

namespace flexmoor::material {
namespace {

using Eigen::Matrix2d;

// The index pairs of the Voigt notation, (11, 22, 12), 0-based.
constexpr int kPair[3][2] = {{0, 0}, {1, 1}, {0, 1}};

// C(p, q) = c(a, b, l, m) with ab the p-th pair and lm the q-th.
template <class Tensor>
Eigen::Matrix3d voigt(const Tensor& c) {
  Eigen::Matrix3d C;
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) C(p, q) = c(kPair[p][0], kPair[p][1], kPair[q][0], kPair[q][1]);
  return C;
}

// x^ab y_ab for a contravariant x and a covariant y.
double contract(const Matrix2d& x, const Matrix2d& y) { return x.cwiseProduct(y).sum(); }

}  // namespace

double thicknessStretchSquared(const Matrix2d& a, const Matrix2d& A) {
  return a.determinant() / A.determinant();
}

LinearElasticPlaneStress::LinearElasticPlaneStress(double youngs_modulus, double poisson_ratio)
    : E_(youngs_modulus), nu_(poisson_ratio) {}

// Eq. 2.40-2.41: T^ab = C^ablm gamma_lm = 2 mu a^al gamma_lm a^mb + lambda a^ab a^lm gamma_lm
// with mu = E / (2 (1 + nu)) and the plane-stress lambda = 2 mu nu / (1 - nu).
MembraneStress LinearElasticPlaneStress::stress(const Matrix2d& a, const Matrix2d& A) const {
  const Matrix2d ai = a.inverse();
  const Matrix2d gamma = 0.5 * (A - a);
  const double mu = E_ / (2.0 * (1.0 + nu_));
  const double lambda = 2.0 * mu * nu_ / (1.0 - nu_);
  MembraneStress out;
  out.T = 2.0 * mu * ai * gamma * ai + lambda * contract(ai, gamma) * ai;
  out.C = voigt([&](int al, int be, int l, int m) {
    return mu * (ai(al, l) * ai(be, m) + ai(al, m) * ai(be, l)) + lambda * ai(al, be) * ai(l, m);
  });
  return out;
}

double LinearElasticPlaneStress::strainEnergyDensity(const Matrix2d& a, const Matrix2d& A) const {
  return 0.5 * contract(stress(a, A).T, 0.5 * (A - a));
}

MooneyRivlinMembrane::MooneyRivlinMembrane(double C1, double C2) : C1_(C1), C2_(C2) {}

// Eq. 2.42 and Appendix B, with l2 = a / A, I_A = a^ab A_ab and
// J = C2 A / a - l2 (C1 + C2 I_A):
//   T^ab = 2 a^ab (C1 + C2 l2) + 2 A^ab J,
//   C^ablm = -4 C2 l2 (a^ab A^lm + A^ab a^lm) - 2 J (A^al A^bm + A^am A^bl)
//            + 4 (C2 A / a + l2 (C1 + C2 I_A)) A^ab A^lm.
MembraneStress MooneyRivlinMembrane::stress(const Matrix2d& a, const Matrix2d& A) const {
  const Matrix2d ai = a.inverse(), Ai = A.inverse();
  const double area_ratio = A.determinant() / a.determinant();  // A / a
  const double l2 = 1.0 / area_ratio;
  const double IA = contract(ai, A);
  const double J = C2_ * area_ratio - l2 * (C1_ + C2_ * IA);
  const double k = 4.0 * (C2_ * area_ratio + l2 * (C1_ + C2_ * IA));
  MembraneStress out;
  out.T = 2.0 * (C1_ + C2_ * l2) * ai + 2.0 * J * Ai;
  out.C = voigt([&](int al, int be, int l, int m) {
    return -4.0 * C2_ * l2 * (ai(al, be) * Ai(l, m) + Ai(al, be) * ai(l, m)) -
           2.0 * J * (Ai(al, l) * Ai(be, m) + Ai(al, m) * Ai(be, l)) + k * Ai(al, be) * Ai(l, m);
  });
  return out;
}

// W = C1 (I1 - 3) + C2 (I2 - 3), I1 = I_A + l2, I2 = A / a + l2 I_A.
double MooneyRivlinMembrane::strainEnergyDensity(const Matrix2d& a, const Matrix2d& A) const {
  const double area_ratio = A.determinant() / a.determinant();
  const double l2 = 1.0 / area_ratio;
  const double IA = contract(a.inverse(), A);
  return C1_ * (IA + l2 - 3.0) + C2_ * (area_ratio + l2 * IA - 3.0);
}

}  // namespace flexmoor::material
