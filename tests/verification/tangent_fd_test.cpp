// Verification of every tangent against central finite differences of the internal force, and of
// the cable laws against docs/theory.md#cable-laws.
//
// Reference: the exact derivative of the element's own internal force, approximated by central
// differences with a step of 1e-6 times the element's size (truncation ~1e-12, round-off ~1e-10
// of the largest entry). Tolerance: max |K - K_fd| <= 1e-6 max |K|, so a wrong term of the tangent
// (Eq. 4.48: geometric part T^11 L^I,1 L^J,1, material part C^1111 (L^I,1 y,1)(L^J,1 y,1)) fails.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "tests/support/cable_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using material::Compression;

constexpr double kRelativeStep = 1e-6;
constexpr double kTangentTolerance = 1e-6;

// Central differences of an element's internal force with respect to each of its dofs.
MatrixXd finiteDifferenceTangent(const element::Element& e, const model::NodalField& X,
                                 model::State state, double h) {
  const int n = e.dofCount();
  MatrixXd K(n, n);
  VectorXd f_plus, f_minus;
  for (int a = 0; a < n; ++a) {
    double& u = state.displacement(a % 3, e.nodes()[a / 3]);
    const double u0 = u;
    u = u0 + h;
    e.internalForce({X, state, 0}, f_plus, nullptr);
    u = u0 - h;
    e.internalForce({X, state, 0}, f_minus, nullptr);
    u = u0;
    K.col(a) = (f_plus - f_minus) / (2.0 * h);
  }
  return K;
}

// max |K - K_fd| / max |K|, with the element's analytic tangent K.
double tangentError(const element::Element& e, const model::NodalField& X,
                    const model::State& state, double h) {
  VectorXd f;
  MatrixXd K;
  e.internalForce({X, state, 0}, f, &K);
  const MatrixXd K_fd = finiteDifferenceTangent(e, X, state, h);
  return (K - K_fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
}

// A rotation about a skew axis, so that no displaced element lies along a coordinate axis.
Eigen::Matrix3d skewRotation() {
  return Eigen::AngleAxisd(0.7, Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
}

// N nodes on a helix (radius 3, pitch 2 per radian), at non-uniform parameters: a curved
// reference element whose interior nodes are not at equal arc lengths.
model::NodalField curvedReference(int N) {
  static const std::vector<std::vector<double>> parameters = {
      {0.0, 1.0}, {0.0, 0.42, 1.0}, {0.0, 0.27, 0.61, 1.0}};
  model::NodalField X(3, N);
  for (int i = 0; i < N; ++i) {
    const double p = parameters[N - 2][i] * 1.2;  // radians
    X.col(i) = Vector3d(3.0 * std::cos(p), 3.0 * std::sin(p), 2.0 * p) + Vector3d(1.0, -2.0, 0.5);
  }
  return X;
}

// A general displaced state: the element scaled by `scale` about its first node, rotated, moved
// and perturbed node by node (the perturbations keep every Gauss point on the same side of
// lambda = 1 as `scale`).
model::State displacedState(const model::NodalField& X, double scale) {
  model::State state(static_cast<int>(X.cols()));
  const Eigen::Matrix3d Q = skewRotation();
  for (int i = 0; i < X.cols(); ++i) {
    const Vector3d perturbation(0.03 * std::sin(1.0 + 2.0 * i), 0.02 * std::cos(3.0 * i),
                                -0.025 * std::sin(0.5 + i));
    const Vector3d y =
        X.col(0) + scale * Q * (X.col(i) - X.col(0)) + Vector3d(0.4, -0.3, 0.2) + perturbation;
    state.displacement.col(i) = y - X.col(i);
  }
  return state;
}

std::vector<int> firstNodes(int N) {
  std::vector<int> nodes(N);
  for (int i = 0; i < N; ++i) nodes[i] = i;
  return nodes;
}

element::CableSection sectionOf(std::shared_ptr<const material::CableMaterial> m) {
  element::CableSection s;
  s.area = 0.01;
  s.density = 7.8;
  s.material = std::move(m);
  return s;
}

std::shared_ptr<const material::CableMaterial> linearElastic(Compression c) {
  return std::make_shared<material::LinearElasticCable>(2.0e7, c);
}
std::shared_ptr<const material::CableMaterial> mooneyRivlin(Compression c) {
  return std::make_shared<material::MooneyRivlinCable>(2300.0, 280.0, c);
}

// The tangent of CableElement<N> against finite differences, at a stretched (scale > 1) or
// shortened (scale < 1) general state; the tensions at the Gauss points must have the sign the
// state was built for, or the check would not be testing what it says.
template <int N>
void expectCableTangent(std::shared_ptr<const material::CableMaterial> material, double scale,
                        const std::string& label) {
  const model::NodalField X = curvedReference(N);
  const model::State state = displacedState(X, scale);
  const element::CableElement<N> cable(firstNodes(N), sectionOf(std::move(material)));
  for (double t : cable.result({X, state, 0}).point_tension)
    ASSERT_GT(scale > 1.0 ? t : -t, 0.0) << label << ": a Gauss point has the wrong sign";
  const double size = (X.col(N - 1) - X.col(0)).norm();
  const double error = tangentError(cable, X, state, kRelativeStep * size);
  std::cout << "[ " << label << " ] max |K - K_fd| / max |K| = " << error << "\n";
  EXPECT_LT(error, kTangentTolerance) << label;
  VectorXd f;
  MatrixXd K;
  cable.internalForce({X, state, 0}, f, &K);
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff())
      << label << ": the tangent of a hyperelastic element is symmetric";
}

template <int N>
void expectCableTangents() {
  const std::string order = "L" + std::to_string(N);
  for (const Compression c : {Compression::Carry, Compression::TensionOnly}) {
    const std::string law = c == Compression::Carry ? "" : " tension-only";
    expectCableTangent<N>(linearElastic(c), 1.15, order + " linear elastic" + law + ", tension");
    expectCableTangent<N>(mooneyRivlin(c), 1.6, order + " Mooney-Rivlin" + law + ", tension");
  }
  // A cable that carries compression (a bar) has a consistent tangent there too.
  expectCableTangent<N>(linearElastic(Compression::Carry), 0.9,
                        order + " linear elastic, compression");
  expectCableTangent<N>(mooneyRivlin(Compression::Carry), 0.8,
                        order + " Mooney-Rivlin, compression");
}

TEST(CableElement, TangentMatchesFiniteDifference) {
  expectCableTangents<2>();
  expectCableTangents<3>();
  expectCableTangents<4>();
}

// Tension-only (slack) cable shortened everywhere: zero internal force and zero tangent, exactly.
TEST(CableElement, SlackCableHasNoForceAndNoStiffness) {
  const auto check = [](const element::Element& e, const model::NodalField& X,
                        const model::State& state, const std::string& label) {
    VectorXd f;
    MatrixXd K;
    e.internalForce({X, state, 0}, f, &K);
    EXPECT_EQ(f.cwiseAbs().maxCoeff(), 0.0) << label;
    EXPECT_EQ(K.cwiseAbs().maxCoeff(), 0.0) << label;
  };
  const model::NodalField X2 = curvedReference(2), X3 = curvedReference(3), X4 = curvedReference(4);
  for (const auto& m :
       {linearElastic(Compression::TensionOnly), mooneyRivlin(Compression::TensionOnly)}) {
    check(element::CableElement<2>(firstNodes(2), sectionOf(m)), X2, displacedState(X2, 0.8), "L2");
    check(element::CableElement<3>(firstNodes(3), sectionOf(m)), X3, displacedState(X3, 0.8), "L3");
    check(element::CableElement<4>(firstNodes(4), sectionOf(m)), X4, displacedState(X4, 0.8), "L4");
  }
}

// Spring N = k (l - l0) along the current chord: tangent k e e^T + (N / l)(I - e e^T) against
// finite differences, stretched and (Compression::Carry) shortened, with a given rest length and
// with the reference distance as rest length. Slack (tension-only, shortened): zero force and
// zero stiffness.
TEST(Spring, TangentMatchesFiniteDifference) {
  model::NodalField X(3, 2);
  X.col(0) = Vector3d(0.5, -1.0, 2.0);
  X.col(1) = Vector3d(3.0, 1.5, 1.0);
  const double length = (X.col(1) - X.col(0)).norm();
  for (const double rest : {-1.0, 0.8 * length}) {
    for (const double scale : {1.3, 0.7}) {
      const model::State state = displacedState(X, scale);
      const element::SpringElement spring(0, 1, 450.0, rest, Compression::Carry);
      const double force = spring.result({X, state, 0}).point_tension[0];
      const double l0 = rest < 0.0 ? length : rest;
      const double l =
          (X.col(1) + state.displacement.col(1) - X.col(0) - state.displacement.col(0)).norm();
      EXPECT_NEAR(force, 450.0 * (l - l0), 1e-12 * 450.0 * l0);
      const double error = tangentError(spring, X, state, kRelativeStep * length);
      std::cout << "[ spring, rest " << l0 << ", force " << force
                << " ] max |K - K_fd| / max |K| = " << error << "\n";
      EXPECT_LT(error, kTangentTolerance);
    }
  }
  const model::State shortened = displacedState(X, 0.7);
  const element::SpringElement slack(0, 1, 450.0, -1.0, Compression::TensionOnly);
  VectorXd f;
  MatrixXd K;
  slack.internalForce({X, shortened, 0}, f, &K);
  EXPECT_EQ(f.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(K.cwiseAbs().maxCoeff(), 0.0);
}

// The assembled tangent on the free dofs of a small 3-D model (a curved L3 cable, an L2 and a
// curved L4 cable in a chain, a spring to a support with a prescribed displacement, gravity)
// against central differences of the assembled free-dof residual R = P - F: K = -dR/du.
// The elements' stiffnesses differ by four orders of magnitude (the L2 cable is Mooney-Rivlin,
// C1 = 2300, the others linear elastic, E = 2e7), so the error is normalised per node pair: for
// each 3 x 3 block of two free nodes, max |K - K_fd| over the block / max |K| over the block, and
// the worst block must be below 1e-8 (measured 2.9e-9, the round-off of the stiff elements'
// forces in the soft element's blocks; margin 3.4; a 1% error in the soft element's tangent gives
// 9e-3 in its blocks, where max |K| of the whole matrix saw 1.8e-6). Blocks of nodes that no
// element joins must be exactly zero in both.
TEST(Assembler, TangentMatchesFiniteDifferenceOfResidual) {
  model::Model m;
  const int a = m.addNode(Vector3d(0.0, 0.0, 0.0));
  const int b = m.addNode(Vector3d(2.2, 0.4, -0.3));
  const int c = m.addNode(Vector3d(5.0, 0.2, 0.1));
  const int d = m.addNode(Vector3d(7.0, 1.0, 0.5));
  const int e = m.addNode(Vector3d(8.1, 1.6, 0.2));
  const int f = m.addNode(Vector3d(9.5, 1.2, -0.6));
  const int g = m.addNode(Vector3d(11.0, 0.5, -1.0));
  const int s = m.addNode(Vector3d(5.0, 3.0, 0.0));
  m.addElement(element::makeCableElement({a, b, c}, sectionOf(linearElastic(Compression::Carry))));
  m.addElement(element::makeCableElement({c, d}, sectionOf(mooneyRivlin(Compression::Carry))));
  m.addElement(
      element::makeCableElement({d, e, f, g}, sectionOf(linearElastic(Compression::Carry)), 6));
  m.addElement(std::make_unique<element::SpringElement>(c, s, 3.0e4, -1.0, Compression::Carry));
  pin(m, a);
  pin(m, g);
  m.constrain(s, 0);
  m.constrain(s, 1);
  m.constrain(s, 2, -0.2);
  m.setGravity(Vector3d(0.0, 0.0, -9.81));
  m.numberEquations();
  const model::Assembler assembler(m);

  model::State state = m.initialState();
  state.load_factor = 1.0;
  for (int n = 0; n < m.nodeCount(); ++n)
    state.displacement.col(n) =
        0.08 * m.reference().col(n) +
        Vector3d(0.05 * std::sin(n), 0.04 * std::cos(2.0 * n), -0.1 * n / 7.0);
  assembler.applyPrescribed(state);

  model::SparseMatrix K_sparse;
  const solve::Residual R0 = solve::outOfBalance(assembler, state, &K_sparse);
  const MatrixXd K = MatrixXd(K_sparse);
  const int n = assembler.equationCount();
  ASSERT_EQ(n, 15);  // nodes b..f free; a, g and s fully constrained
  const double h = kRelativeStep * 11.0;
  MatrixXd K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    model::State plus = state, minus = state;
    assembler.addFree(VectorXd::Unit(n, j) * h, plus.displacement);
    assembler.addFree(-VectorXd::Unit(n, j) * h, minus.displacement);
    K_fd.col(j) = -(solve::outOfBalance(assembler, plus, nullptr).free -
                    solve::outOfBalance(assembler, minus, nullptr).free) /
                  (2.0 * h);
  }
  const std::vector<int> free_nodes = {b, c, d, e, f};
  double worst = 0.0;
  for (const int i : free_nodes)
    for (const int j : free_nodes) {
      MatrixXd block(3, 3), block_fd(3, 3);
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) {
          block(r, k) = K(m.equation(i, r), m.equation(j, k));
          block_fd(r, k) = K_fd(m.equation(i, r), m.equation(j, k));
        }
      const double size = block.cwiseAbs().maxCoeff();
      if (size == 0.0) {
        EXPECT_EQ(block_fd.cwiseAbs().maxCoeff(), 0.0) << "nodes " << i << ", " << j;
        continue;
      }
      const double error = (block - block_fd).cwiseAbs().maxCoeff() / size;
      EXPECT_LT(error, 1e-8) << "nodes " << i << ", " << j;
      worst = std::max(worst, error);
    }
  std::cout << "[ assembled ] worst node-pair block max |K - K_fd| / max |K| = " << worst
            << " (whole matrix " << (K - K_fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff()
            << "), |R| = " << R0.free.norm() << "\n";
}

// ---------------------------------------------------------------------------------------------
// The laws. a11 = 2.7 (a reference element that is not unit-parametrised) so that the convected
// scalings a^11 = 1 / a11 are tested, not just the physical law.

constexpr double kA11 = 2.7;

material::CableStress stressAt(const material::CableMaterial& m, double stretch) {
  return m.stress(kA11, stretch * stretch * kA11);
}

// C^1111 = dT^11 / d gamma11 against central differences in gamma11 = (A11 - a11) / 2, step 1e-6
// of a11, tolerance 1e-7 relative (smooth scalar: truncation ~1e-12, round-off ~1e-10).
TEST(CableMaterial, MaterialTangentMatchesFiniteDifference) {
  const material::LinearElasticCable linear(2.0e7, Compression::Carry);
  const material::MooneyRivlinCable mooney(2300.0, 280.0, Compression::Carry);
  const material::EngineeringStrainCable engineering(2.0e7, Compression::Carry);
  for (const material::CableMaterial* law :
       {static_cast<const material::CableMaterial*>(&linear),
        static_cast<const material::CableMaterial*>(&mooney),
        static_cast<const material::CableMaterial*>(&engineering)})
    for (const double stretch : {0.7, 0.95, 1.0, 1.02, 1.3, 2.5}) {
      const double A11 = stretch * stretch * kA11, dgamma = 1e-6 * kA11;
      const double fd =
          (law->stress(kA11, A11 + 2.0 * dgamma).T11 - law->stress(kA11, A11 - 2.0 * dgamma).T11) /
          (2.0 * dgamma);
      const double C = law->stress(kA11, A11).C1111;
      EXPECT_NEAR(C, fd, 1e-7 * std::abs(C)) << law->name() << " at stretch " << stretch;
    }
}

// Eq. 2.53 and 2.54 as docs/theory.md#cable-laws writes them in convected components, against the code:
// linear elastic T^11 = E a^11 a^11 gamma11, C^1111 = E (a^11)^2; Mooney-Rivlin
// T^11 = 2 (C1 + lc^2 C2)(a^11 - lc^2 A^11) with lc^2 = 1 / lambda. Tolerance 1e-13 relative.
TEST(CableMaterial, ConvectedStressMatchesFormulation) {
  const double E = 2.0e7, C1 = 2300.0, C2 = 280.0;
  const material::LinearElasticCable linear(E, Compression::Carry);
  const material::MooneyRivlinCable mooney(C1, C2, Compression::Carry);
  for (const double stretch : {0.7, 1.02, 1.3, 2.5}) {
    const double A11 = stretch * stretch * kA11, gamma = 0.5 * (A11 - kA11);
    const material::CableStress l = linear.stress(kA11, A11);
    EXPECT_NEAR(l.T11, E * gamma / (kA11 * kA11), 1e-13 * std::abs(l.T11));
    EXPECT_NEAR(l.C1111, E / (kA11 * kA11), 1e-13 * E / (kA11 * kA11));
    const double lc2 = 1.0 / stretch;
    const double T11 = 2.0 * (C1 + lc2 * C2) * (1.0 / kA11 - lc2 / A11);
    EXPECT_NEAR(mooney.stress(kA11, A11).T11, T11, 1e-13 * std::abs(T11));
  }
}

// Mooney-Rivlin physical checks (docs/theory.md): the Cauchy stress of the incompressible cable,
// axial force / current area = N lambda / A0, is 2 (lambda^2 - 1/lambda)(C1 + C2 / lambda);
// zero at lambda = 1; its small-strain Young's modulus d sigma / d lambda at lambda = 1 is
// 6 (C1 + C2). The linear-elastic force is N = EA lambda (lambda^2 - 1) / 2 with small-strain
// stiffness dN/dlambda = EA. Tolerances: 1e-13 relative for the closed forms, 1e-7 for the
// finite-difference slopes.
TEST(CableMaterial, MooneyRivlinCauchyStressAndLinearForce) {
  const double C1 = 2300.0, C2 = 280.0, E = 2.0e7, A0 = 0.01;
  const material::MooneyRivlinCable mooney(C1, C2, Compression::Carry);
  const material::LinearElasticCable linear(E, Compression::Carry);
  const auto cauchy = [&](double l) { return mooney.tension(kA11, l * l * kA11, A0) * l / A0; };
  const auto force = [&](double l) { return linear.tension(kA11, l * l * kA11, A0); };
  for (const double l : {0.7, 1.02, 1.3, 2.5, 4.0}) {
    const double expected = 2.0 * (l * l - 1.0 / l) * (C1 + C2 / l);
    EXPECT_NEAR(cauchy(l), expected, 1e-13 * std::abs(expected)) << "stretch " << l;
    const double N = 0.5 * E * A0 * l * (l * l - 1.0);
    EXPECT_NEAR(force(l), N, 1e-13 * std::abs(N)) << "stretch " << l;
  }
  EXPECT_EQ(cauchy(1.0), 0.0);
  EXPECT_EQ(force(1.0), 0.0);
  const double dl = 1e-6;
  EXPECT_NEAR((cauchy(1.0 + dl) - cauchy(1.0 - dl)) / (2.0 * dl), 6.0 * (C1 + C2),
              1e-7 * 6.0 * (C1 + C2));
  EXPECT_NEAR((force(1.0 + dl) - force(1.0 - dl)) / (2.0 * dl), E * A0, 1e-7 * E * A0);
}

// The mooring codes' law: axial force N = EA (lambda - 1) exactly (1e-13 relative) at every
// stretch, compressed or stretched, and the initial modulus E.
TEST(CableMaterial, EngineeringStrainForceIsLinearInTheStretch) {
  const double E = 2.0e7, A0 = 0.01;
  const material::EngineeringStrainCable law(E, Compression::Carry);
  for (const double l : {0.7, 1.0, 1.002, 1.3, 2.5}) {
    const double N = E * A0 * (l - 1.0);
    EXPECT_NEAR(law.tension(kA11, l * l * kA11, A0), N, 1e-13 * E * A0) << "stretch " << l;
  }
  EXPECT_EQ(law.initialModulus(), E);
}

// Tension-only: zero stress and zero stiffness when shortened, the full law when stretched.
TEST(CableMaterial, TensionOnlyIsSlackInCompression) {
  const material::LinearElasticCable linear(2.0e7, Compression::TensionOnly);
  const material::MooneyRivlinCable mooney(2300.0, 280.0, Compression::TensionOnly);
  const material::LinearElasticCable linear_bar(2.0e7, Compression::Carry);
  const material::MooneyRivlinCable mooney_bar(2300.0, 280.0, Compression::Carry);
  for (const double stretch : {0.5, 0.9, 0.999}) {
    EXPECT_EQ(stressAt(linear, stretch).T11, 0.0);
    EXPECT_EQ(stressAt(linear, stretch).C1111, 0.0);
    EXPECT_EQ(stressAt(mooney, stretch).T11, 0.0);
    EXPECT_EQ(stressAt(mooney, stretch).C1111, 0.0);
    EXPECT_EQ(linear.tension(kA11, stretch * stretch * kA11, 0.01), 0.0);
    EXPECT_LT(stressAt(linear_bar, stretch).T11, 0.0);  // the bar does carry it
    EXPECT_LT(stressAt(mooney_bar, stretch).T11, 0.0);
  }
  for (const double stretch : {1.001, 1.5}) {
    EXPECT_EQ(stressAt(linear, stretch).T11, stressAt(linear_bar, stretch).T11);
    EXPECT_EQ(stressAt(linear, stretch).C1111, stressAt(linear_bar, stretch).C1111);
    EXPECT_EQ(stressAt(mooney, stretch).T11, stressAt(mooney_bar, stretch).T11);
    EXPECT_EQ(stressAt(mooney, stretch).C1111, stressAt(mooney_bar, stretch).C1111);
  }
}

}  // namespace
}  // namespace flexmoor::test
