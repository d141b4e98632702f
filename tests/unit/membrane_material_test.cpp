// Membrane constitutive laws in convected coordinates (Eq. 2.40-2.42, Appendix B).
//
// The convected components are checked two ways: internally (the tangent against finite
// differences of the stress, the stress against finite differences of the strain energy) and
// physically, by building the metrics from a skewed, non-unit reference basis g_a of a plane
// with an orthonormal frame, deforming it by a known in-plane stretch U, and comparing the
// physical second Piola-Kirchhoff stress S = T^ab g_a g_b with closed forms.
#include "libstruct/material/membrane_material.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace flexmoor::test {
namespace {

using Eigen::Matrix2d;
using Eigen::Matrix3d;
using material::LinearElasticPlaneStress;
using material::MembraneMaterial;
using material::MooneyRivlinMembrane;

// A general non-orthogonal reference basis and a general deformation in 3D:
// a_ab = x,a . x,b and A_ab = (F x,a) . (F x,b).
struct Metrics {
  Matrix2d a, A;
};

Metrics generalMetrics() {
  Eigen::Matrix<double, 3, 2> X;
  X << 1.2, 0.4, 0.1, 0.9, 0.3, -0.2;  // columns x,1 and x,2
  Matrix3d F;
  F << 1.3, 0.2, 0.1, -0.1, 0.8, 0.25, 0.05, 0.15, 1.1;
  const Eigen::Matrix<double, 3, 2> Y = F * X;
  return {X.transpose() * X, Y.transpose() * Y};
}

// Columns of G: the reference basis vectors g_1, g_2 in an orthonormal frame of the plane.
Matrix2d skewedBasis() {
  Matrix2d G;
  G << 1.3, 0.4, 0.2, 0.8;
  return G;
}

// Physical stress S = G T G^T of a state stretched by U (symmetric, in the orthonormal frame)
// from the reference basis G: a = G^T G, A = G^T U^T U G.
Matrix2d physicalStress(const MembraneMaterial& law, const Matrix2d& G, const Matrix2d& U) {
  const Matrix2d T = law.stress(G.transpose() * G, G.transpose() * U.transpose() * U * G).T;
  return G * T * G.transpose();
}

// [T^11, T^22, T^12].
Eigen::Vector3d voigt(const Matrix2d& T) { return {T(0, 0), T(1, 1), T(0, 1)}; }

// dT / d[gamma_11, gamma_22, 2 gamma_12] by central differences: gamma_11 moves A_11 by 2 h,
// the engineering shear 2 gamma_12 moves A_12 and A_21 by h each.
Matrix3d finiteDifferenceTangent(const MembraneMaterial& law, const Metrics& m, double h) {
  Matrix3d C;
  for (int q = 0; q < 3; ++q) {
    Matrix2d dA = Matrix2d::Zero();
    if (q < 2)
      dA(q, q) = 2.0 * h;
    else
      dA(0, 1) = dA(1, 0) = h;
    C.col(q) = voigt(law.stress(m.a, m.A + dA).T - law.stress(m.a, m.A - dA).T) / (2.0 * h);
  }
  return C;
}

// T^ab = 2 dW/dA_ab by central differences (A_12 and A_21 moved together).
Matrix2d finiteDifferenceStress(const MembraneMaterial& law, const Metrics& m, double h) {
  Matrix2d T;
  for (int al = 0; al < 2; ++al)
    for (int be = al; be < 2; ++be) {
      Matrix2d dA = Matrix2d::Zero();
      dA(al, be) = dA(be, al) = h;
      const double dW =
          law.strainEnergyDensity(m.a, m.A + dA) - law.strainEnergyDensity(m.a, m.A - dA);
      T(al, be) = T(be, al) = (al == be ? 2.0 : 1.0) * dW / (2.0 * h);
    }
  return T;
}

double maxAbs(const Matrix3d& C) { return C.cwiseAbs().maxCoeff(); }

const LinearElasticPlaneStress kRubberLinear(3.0e6, 0.3);
const MooneyRivlinMembrane kRubber(0.3e6, 0.08e6);

// The analytic tangent against central differences of T^ab (step 1e-6 of metrics of order 1),
// at a general non-diagonal state; 1e-6 relative to the largest entry.
TEST(MembraneMaterial, LinearElasticTangentMatchesFiniteDifference) {
  const Metrics m = generalMetrics();
  const Matrix3d C = kRubberLinear.stress(m.a, m.A).C;
  EXPECT_LT(maxAbs(C - finiteDifferenceTangent(kRubberLinear, m, 1e-6)), 1e-6 * maxAbs(C));
}

TEST(MembraneMaterial, MooneyRivlinTangentMatchesFiniteDifference) {
  const Metrics m = generalMetrics();
  const Matrix3d C = kRubber.stress(m.a, m.A).C;
  EXPECT_LT(maxAbs(C - finiteDifferenceTangent(kRubber, m, 1e-6)), 1e-6 * maxAbs(C));
}

// T^ab = 2 dW/dA_ab: each law's stress is the gradient of its strain energy (1e-6 relative).
TEST(MembraneMaterial, StressIsTwiceEnergyGradientForBothLaws) {
  const Metrics m = generalMetrics();
  for (const MembraneMaterial* law : {static_cast<const MembraneMaterial*>(&kRubberLinear),
                                      static_cast<const MembraneMaterial*>(&kRubber)}) {
    const Matrix2d T = law->stress(m.a, m.A).T;
    EXPECT_LT((T - finiteDifferenceStress(*law, m, 1e-6)).cwiseAbs().maxCoeff(),
              1e-6 * T.cwiseAbs().maxCoeff())
        << law->name();
  }
}

// Both symmetries the element relies on: T^ab = T^ba, and C^ablm = C^lmab (hyperelastic laws,
// so the material stiffness B^T C B is symmetric); 1e-12 relative.
TEST(MembraneMaterial, StressAndTangentAreSymmetricForBothLaws) {
  const Metrics m = generalMetrics();
  for (const MembraneMaterial* law : {static_cast<const MembraneMaterial*>(&kRubberLinear),
                                      static_cast<const MembraneMaterial*>(&kRubber)}) {
    const material::MembraneStress s = law->stress(m.a, m.A);
    EXPECT_NEAR(s.T(0, 1), s.T(1, 0), 1e-12 * s.T.cwiseAbs().maxCoeff()) << law->name();
    EXPECT_LT(maxAbs(s.C - s.C.transpose()), 1e-12 * maxAbs(s.C)) << law->name();
  }
}

// Uniaxial stress: Green strains e along the first axis and -nu e across give
// S = diag(E e, 0) exactly (the law is linear in the Green strain); 1e-9 relative to E e.
TEST(MembraneMaterial, LinearElasticUniaxialStressIsYoungsModulusTimesStrain) {
  const double E = 3.0e6, nu = 0.3, e = 0.04;
  const LinearElasticPlaneStress law(E, nu);
  const Matrix2d U =
      Eigen::Vector2d(std::sqrt(1.0 + 2.0 * e), std::sqrt(1.0 - 2.0 * nu * e)).asDiagonal();
  const Matrix2d S = physicalStress(law, skewedBasis(), U);
  EXPECT_NEAR(S(0, 0), E * e, 1e-9 * E * e);
  EXPECT_NEAR(S(1, 1), 0.0, 1e-9 * E * e);
  EXPECT_NEAR(S(0, 1), 0.0, 1e-9 * E * e);
}

// Simple shear of Green strain gamma_12 = g gives S_12 = 2 G g with G = E / (2 (1 + nu)).
TEST(MembraneMaterial, LinearElasticShearStressIsShearModulusTimesEngineeringStrain) {
  const double E = 3.0e6, nu = 0.3, g = 0.02;
  const LinearElasticPlaneStress law(E, nu);
  const Matrix2d G = skewedBasis();
  Matrix2d strain;
  strain << 0.0, g, g, 0.0;
  const Matrix2d T =
      law.stress(G.transpose() * G, G.transpose() * (Matrix2d::Identity() + 2.0 * strain) * G).T;
  const Matrix2d S = G * T * G.transpose();
  EXPECT_NEAR(S(0, 1), E / (1.0 + nu) * g, 1e-9 * E * g);
  EXPECT_NEAR(S(0, 0), 0.0, 1e-9 * E * g);
  EXPECT_NEAR(S(1, 1), 0.0, 1e-9 * E * g);
}

// Cylinder (docs/theory.md): axial stretch 1, hoop stretch L gives the physical hoop stress
// S = 2 (C1 + C2)(1 - L^-4) and, from the principal-stretch form of the law, the axial stress
// 2 C1 (1 - L^-2) + 2 C2 (L^2 - 1); 1e-12 relative.
TEST(MembraneMaterial, MooneyRivlinCylinderHoopStressMatchesClosedForm) {
  const double C1 = 0.3e6, C2 = 0.08e6;
  const MooneyRivlinMembrane law(C1, C2);
  for (const double L : {0.8, 1.1, 1.7, 3.0}) {
    const Matrix2d S = physicalStress(law, skewedBasis(), Eigen::Vector2d(1.0, L).asDiagonal());
    const double hoop = 2.0 * (C1 + C2) * (1.0 - std::pow(L, -4));
    const double axial = 2.0 * C1 * (1.0 - 1.0 / (L * L)) + 2.0 * C2 * (L * L - 1.0);
    const double scale = std::abs(hoop) + std::abs(axial);
    EXPECT_NEAR(S(1, 1), hoop, 1e-12 * scale) << "L = " << L;
    EXPECT_NEAR(S(0, 0), axial, 1e-12 * scale) << "L = " << L;
    EXPECT_NEAR(S(0, 1), 0.0, 1e-12 * scale) << "L = " << L;
  }
}

// General biaxial stretch along rotated principal axes: S_i = sigma_i / lambda_i^2 with the
// Cauchy stresses of incompressible Mooney-Rivlin in plane stress,
// sigma_i = 2 C1 (lambda_i^2 - lambda_3^2) - 2 C2 (lambda_i^-2 - lambda_3^-2),
// lambda_3 = 1 / (lambda_1 lambda_2); 1e-12 relative.
TEST(MembraneMaterial, MooneyRivlinBiaxialStressMatchesPrincipalStretchForm) {
  const double C1 = 0.3e6, C2 = 0.08e6, l1 = 1.4, l2 = 0.9, angle = 0.6;
  const MooneyRivlinMembrane law(C1, C2);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Matrix2d U = R * Eigen::Vector2d(l1, l2).asDiagonal() * R.transpose();
  const Matrix2d S = R.transpose() * physicalStress(law, skewedBasis(), U) * R;
  const double l3 = 1.0 / (l1 * l2);
  auto principal = [&](double li) {
    return (2.0 * C1 * (li * li - l3 * l3) - 2.0 * C2 * (1.0 / (li * li) - 1.0 / (l3 * l3))) /
           (li * li);
  };
  const double scale = std::abs(principal(l1)) + std::abs(principal(l2));
  EXPECT_NEAR(S(0, 0), principal(l1), 1e-12 * scale);
  EXPECT_NEAR(S(1, 1), principal(l2), 1e-12 * scale);
  EXPECT_NEAR(S(0, 1), 0.0, 1e-12 * scale);
}

// No stress in the reference state, and there the tangent is the plane-stress linear one of an
// incompressible solid: E = 6 (C1 + C2), nu = 1/2 (1e-12 relative).
TEST(MembraneMaterial, MooneyRivlinSmallStrainLimitIsIncompressibleLinearElastic) {
  const double C1 = 0.3e6, C2 = 0.08e6;
  const Metrics m = generalMetrics();
  const material::MembraneStress s = MooneyRivlinMembrane(C1, C2).stress(m.a, m.a);
  EXPECT_LT(s.T.cwiseAbs().maxCoeff(), 1e-12 * C1);
  const Matrix3d linear = LinearElasticPlaneStress(6.0 * (C1 + C2), 0.5).stress(m.a, m.a).C;
  EXPECT_LT(maxAbs(s.C - linear), 1e-12 * maxAbs(linear));
}

// Incompressibility: l2 = a / A is the inverse square of the area stretch, independent of the
// reference basis; here principal stretches 1.4 and 0.9 (1e-14 relative).
TEST(MembraneMaterial, ThicknessStretchConservesVolume) {
  const Matrix2d G = skewedBasis();
  const Matrix2d U = Eigen::Vector2d(1.4, 0.9).asDiagonal();
  const double l2 = material::thicknessStretchSquared(G.transpose() * G, G.transpose() * U * U * G);
  EXPECT_NEAR(l2, 1.0 / (1.4 * 1.4 * 0.9 * 0.9), 1e-14);
}

}  // namespace
}  // namespace flexmoor::test
