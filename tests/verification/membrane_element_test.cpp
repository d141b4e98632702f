// Membrane elements (Eq. 3.17, 4.28-4.41): tangents and pressure load stiffness against central
// finite differences, patch tests, rigid rotation, and the inflated tube of Example 3 against
// Green & Adkins' exact solution.
#include "libstruct/element/membrane_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/membrane_models.hpp"

namespace {

using namespace flexmoor;
using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;

struct ShapeCase {
  std::string shape;
  int nodes;
};
void PrintTo(const ShapeCase& c, std::ostream* os) { *os << c.shape << c.nodes; }

Vector2d naturalNode(const ShapeCase& s, int i) {
  if (s.shape == "quad") {
    if (s.nodes == 4) return shape::QuadShape<4>::node(i);
    if (s.nodes == 8) return shape::QuadShape<8>::node(i);
    return shape::QuadShape<12>::node(i);
  }
  if (s.nodes == 3) return shape::TriangleShape<3>::node(i);
  if (s.nodes == 6) return shape::TriangleShape<6>::node(i);
  return shape::TriangleShape<10>::node(i);
}

std::shared_ptr<material::MembraneMaterial> mooneyRivlin() {
  return std::make_shared<material::MooneyRivlinMembrane>(2300.0, 280.0);
}
std::shared_ptr<material::MembraneMaterial> linearElastic() {
  return std::make_shared<material::LinearElasticPlaneStress>(1.0e4, 0.3);
}

// Central differences of a nodal vector function of the displacement: relative max error.
double finiteDifferenceError(
    const model::NodalField& X, const model::State& s,
    const std::function<void(const element::ElementContext&, VectorXd&, MatrixXd*)>& f) {
  VectorXd value, plus, minus;
  MatrixXd analytic;
  f({X, s, 0}, value, &analytic);
  MatrixXd numeric(analytic.rows(), analytic.cols());
  const double h = 1e-6;
  for (int j = 0; j < numeric.cols(); ++j) {
    model::State sp = s, sm = s;
    sp.displacement.data()[j] += h;
    sm.displacement.data()[j] -= h;
    f({X, sp, 0}, plus, nullptr);
    f({X, sm, 0}, minus, nullptr);
    numeric.col(j) = (plus - minus) / (2.0 * h);
  }
  return (analytic - numeric).cwiseAbs().maxCoeff() / analytic.cwiseAbs().maxCoeff();
}

class MembraneShapes : public ::testing::TestWithParam<ShapeCase> {
 protected:
  // A curved element: the reference cell mapped onto a doubly curved surface, and a general
  // stretched, sheared and lifted displaced state.
  void build(std::shared_ptr<material::MembraneMaterial> law) {
    const ShapeCase c = GetParam();
    std::vector<int> nodes(c.nodes);
    for (int i = 0; i < c.nodes; ++i) nodes[i] = i;
    element_ = element::makeMembraneElement(c.shape, nodes, {0.01, 2.0, law});
    X_.resize(3, c.nodes);
    state_ = model::State(c.nodes);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-0.05, 0.05);
    for (int i = 0; i < c.nodes; ++i) {
      const Vector2d p = naturalNode(c, i);
      X_.col(i) << 2.0 * p.x() + 0.1 * p.y(), 1.5 * p.y(),
          0.3 * p.x() * p.x() + 0.1 * p.y() * p.y();
      state_.displacement.col(i) << 0.3 * X_(0, i) + noise(rng), 0.2 * X_(1, i) + noise(rng),
          0.1 * X_(0, i) + noise(rng);
    }
  }
  std::unique_ptr<element::Element> element_;
  model::NodalField X_;
  model::State state_;
};

// Reference: central differences of the internal force (Eq. 4.39); tolerance 1e-6 relative.
TEST_P(MembraneShapes, TangentMatchesFiniteDifference) {
  for (auto law : {mooneyRivlin(), linearElastic()}) {
    build(law);
    EXPECT_LT(finiteDifferenceError(X_, state_,
                                    [&](const element::ElementContext& c, VectorXd& f,
                                        MatrixXd* K) { element_->internalForce(c, f, K); }),
              1e-6)
        << law->name();
  }
}

// Reference: central differences of the follower-pressure load (Eq. 3.37); tolerance 1e-6.
TEST_P(MembraneShapes, PressureLoadStiffnessMatchesFiniteDifference) {
  build(mooneyRivlin());
  EXPECT_LT(finiteDifferenceError(X_, state_,
                                  [&](const element::ElementContext& c, VectorXd& f, MatrixXd* K) {
                                    element_->pressureLoad(c, 3.0, f, K);
                                  }),
            1e-6);
}

// A finite rigid rotation of a curved element strains nothing: zero internal force (relative to
// the force of a 1% stretch), zero stress resultant.
TEST_P(MembraneShapes, RigidRotationGivesZeroStrain) {
  build(linearElastic());
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.9, Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  model::State rotated(GetParam().nodes), stretched(GetParam().nodes);
  for (int i = 0; i < GetParam().nodes; ++i) {
    rotated.displacement.col(i) = R * X_.col(i) - X_.col(i);
    stretched.displacement.col(i) = 0.01 * X_.col(i);
  }
  VectorXd f_rotated, f_stretched;
  element_->internalForce({X_, rotated, 0}, f_rotated, nullptr);
  element_->internalForce({X_, stretched, 0}, f_stretched, nullptr);
  EXPECT_LT(f_rotated.norm(), 1e-10 * f_stretched.norm());
}

// Lumped mass (HRZ): diagonal, every entry positive (also at the corners of Q8, Q12, T6, T10,
// where row sums would be negative or zero), the same total per direction as the consistent mass.
TEST_P(MembraneShapes, LumpedMassIsPositiveDiagonalWithTheConsistentTotal) {
  build(linearElastic());
  const model::State s(GetParam().nodes);
  Eigen::MatrixXd consistent, lumped;
  element_->mass({X_, s, 0}, element::MassKind::Consistent, consistent);
  element_->mass({X_, s, 0}, element::MassKind::Lumped, lumped);
  const Eigen::MatrixXd diagonal = lumped.diagonal().asDiagonal();
  EXPECT_EQ((lumped - diagonal).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(lumped.diagonal().minCoeff(), 0.0);
  EXPECT_NEAR(lumped.sum(), consistent.sum(), 1e-12 * consistent.sum());
}

// Patch test: a flat, distorted (straight-sided) element under the displacement of a uniform
// biaxial stretch with shear reproduces the uniform stress exactly at every integration point
// and its nodal forces sum to zero. Reference: the plane-stress law at the imposed Green strain.
TEST_P(MembraneShapes, UniformStretchIsReproducedExactly) {
  const ShapeCase c = GetParam();
  std::vector<int> nodes(c.nodes);
  for (int i = 0; i < c.nodes; ++i) nodes[i] = i;
  const double E = 1.0e4, nu = 0.3, h0 = 0.01;
  auto e = element::makeMembraneElement(
      c.shape, nodes, {h0, 1.0, std::make_shared<material::LinearElasticPlaneStress>(E, nu)});
  // An affine map of the reference cell keeps edges straight and mid-side nodes in place.
  Eigen::Matrix2d J;
  J << 1.3, 0.4, -0.2, 0.9;
  model::NodalField X(3, c.nodes);
  model::State s(c.nodes);
  Eigen::Matrix2d F;  // deformation gradient of the patch
  F << 1.05, 0.02, 0.01, 0.97;
  for (int i = 0; i < c.nodes; ++i) {
    const Vector2d x = J * naturalNode(c, i) + Vector2d(0.5, -0.3);
    X.col(i) << x, 0.0;
    s.displacement.col(i) << F * x - x, 0.0;
  }
  const Eigen::Matrix2d green = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
  // Cartesian plane stress: S = E/(1-nu^2) [(1-nu) green + nu tr(green) I]
  const Eigen::Matrix2d S =
      E / (1.0 - nu * nu) * ((1.0 - nu) * green + nu * green.trace() * Eigen::Matrix2d::Identity());
  // Cauchy resultant n = h0 / det F * F S F^T (per current length)
  const Eigen::Matrix2d n = h0 / F.determinant() * F * S * F.transpose();
  const element::ElementResult r = e->result({X, s, 0});
  ASSERT_FALSE(r.point_resultant.empty());
  for (const Eigen::Matrix3d& p : r.point_resultant)
    EXPECT_LT((p.topLeftCorner<2, 2>() - n).cwiseAbs().maxCoeff(), 1e-10 * n.norm());
  VectorXd f;
  e->internalForce({X, s, 0}, f, nullptr);
  Vector3d sum = Vector3d::Zero();
  for (int i = 0; i < c.nodes; ++i) sum += f.segment<3>(3 * i);
  EXPECT_LT(sum.norm(), 1e-10 * f.norm());
}

INSTANTIATE_TEST_SUITE_P(AllShapes, MembraneShapes,
                         ::testing::Values(ShapeCase{"quad", 4}, ShapeCase{"quad", 8},
                                           ShapeCase{"quad", 12}, ShapeCase{"triangle", 3},
                                           ShapeCase{"triangle", 6}, ShapeCase{"triangle", 10}),
                         [](const auto& info) {
                           return info.param.shape + std::to_string(info.param.nodes);
                         });

// Axisymmetric membrane and hoop cable: tangents and pressure stiffness against central
// differences; tolerance 1e-6 relative.
TEST(AxisymmetricMembrane, TangentAndPressureStiffnessMatchFiniteDifference) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  for (int n : {2, 3, 4}) {
    std::vector<int> nodes(n);
    for (int i = 0; i < n; ++i) nodes[i] = i;
    auto e = element::makeAxisymmetricMembrane(nodes, {0.01, 1.0, mooneyRivlin()});
    model::NodalField X(3, n);
    model::State s(n);
    for (int i = 0; i < n; ++i) {
      const double t = double(i) / (n - 1);
      X.col(i) << 2.0 + t + 0.2 * t * t, 0.0, 3.0 * t;
      s.displacement.col(i) << 0.5 + noise(rng), 0.0, noise(rng);
    }
    EXPECT_LT(finiteDifferenceError(X, s,
                                    [&](const element::ElementContext& c, VectorXd& f,
                                        MatrixXd* K) { e->internalForce(c, f, K); }),
              1e-6)
        << n;
    EXPECT_LT(finiteDifferenceError(X, s,
                                    [&](const element::ElementContext& c, VectorXd& f,
                                        MatrixXd* K) { e->pressureLoad(c, 3.0, f, K); }),
              1e-6)
        << n;
  }
}

TEST(HoopCable, RadialStiffnessMatchesFiniteDifference) {
  element::HoopCable ring(0, {0.012272, 1.0,
                              std::make_shared<material::MooneyRivlinCable>(
                                  14000.0, 4000.0, material::Compression::Carry)});
  model::NodalField X(3, 1);
  X << 10.0, 0.0, 1.0;
  model::State s(1);
  s.displacement(0, 0) = 3.0;
  const double error =
      finiteDifferenceError(X, s, [&](const element::ElementContext& c, VectorXd& f, MatrixXd* K) {
        ring.internalForce(c, f, K);
      });
  EXPECT_LT(error, 1e-6);
}

// Example 3 (docs/theory.md#example-3, Green & Adkins): radial displacement (lambda - 1) R at p = 1..5,
// including p = 5 where the stretch is about 2.38. Newton with the consistent pressure load
// stiffness, one increment per unit of pressure. Tolerances just above the largest measured
// error of each model: 2 x Q8 0.584% (at p = 5) -> 0.65%; axisymmetric (2 quadratic elements, the
// exact plane-strain tube up to round-off) 5.7e-14 -> 1e-12; 16 x Q4 1.58% (p = 5) -> 1.7%.
struct TubeModel {
  const char* name;
  std::function<std::unique_ptr<model::Model>(const test::TubeInputs&)> build;
  double tolerance;
};
// Test names, not bytes, in ctest's listing.
void PrintTo(const TubeModel& m, std::ostream* os) { *os << m.name; }

class Example3 : public ::testing::TestWithParam<TubeModel> {};

TEST_P(Example3, RadialDisplacementMatchesGreenAdkins) {
  const test::TubeInputs tube;
  auto m = GetParam().build(tube);
  model::Assembler assembler(*m);
  model::State s = m->initialState();
  for (int p = 1; p <= 5; ++p) {
    solve::StaticOptions o;
    o.load_factor = p;
    o.pressure_load_stiffness = true;
    solve::solveStatic(assembler, s, o);
    const double exact = (test::tubeStretchAtPressure(tube, p) - 1.0) * tube.radius;
    const double radial = s.displacement(0, 0);
    std::cout << "[ " << GetParam().name << " ] p = " << p << ": relative error "
              << (radial - exact) / exact << "\n";
    EXPECT_NEAR(radial, exact, GetParam().tolerance * exact) << "p = " << p;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Models, Example3,
    ::testing::Values(
        TubeModel{"TwoQ8", [](const test::TubeInputs& t) { return test::quarterTube(t, 2, 8); },
                  0.0065},
        TubeModel{"Axisymmetric",
                  [](const test::TubeInputs& t) { return test::axisymmetricTube(t, 2, 3); }, 1e-12},
        TubeModel{"SixteenQ4",
                  [](const test::TubeInputs& t) { return test::quarterTube(t, 16, 4); }, 0.017}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
