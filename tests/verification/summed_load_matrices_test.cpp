// The elements' summed load matrices (element::LoadMatrices::summed): with weights k, c, m set,
// an element puts k (-dp/du) + c (-dp/du') + m (-dp/du'') into its stiffness matrix point by
// point, which the time integrator's effective tangent takes (Eq. 4.63). Reference: the same
// element's three matrices computed apart and summed afterwards. Metric: max |difference| / max
// |sum|. Tolerance 2e-15: the two differ by the order of the floating-point sums only (measured
// 0.8e-16 to 3.5e-16; the bound about six times that).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "tests/support/oblique_dashpot.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr element::LoadMatrices::Weights kWeights{1.1, 37.0, 450.0};

double summedError(const std::function<void(element::LoadMatrices&)>& evaluate) {
  element::LoadMatrices apart, summed;
  evaluate(apart);
  summed.summed = kWeights;
  evaluate(summed);
  const MatrixXd reference = kWeights.stiffness * apart.stiffness +
                             kWeights.damping * apart.damping + kWeights.mass * apart.mass;
  EXPECT_GT(reference.cwiseAbs().maxCoeff(), 0.0);
  return (summed.stiffness - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

// A load linear in the point's position, tangent, velocity and acceleration, with fixed
// non-symmetric derivatives: every matrix of lineLoad is non-zero.
class LinearLineLoad final : public model::LineLoad {
 public:
  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override {
    model::PointForce f;
    f.force = dy_ * p.position + dt_ * p.tangent + dv_ * p.velocity + da_ * p.acceleration;
    if (!jacobians) return f;
    f.d_position = dy_;
    f.d_tangent = dt_;
    f.d_velocity = dv_;
    f.d_acceleration = da_;
    return f;
  }

 private:
  Matrix3d dy_ = (Matrix3d() << 2, -1, 0.5, 0.3, 4, -2, 1, 0.2, 3).finished();
  Matrix3d dt_ = (Matrix3d() << 0.5, 2, 0, -1, 0.1, 0.7, 0.4, 0.3, -0.6).finished();
  Matrix3d dv_ = (Matrix3d() << 10, 1, -3, 2, 8, 0.5, -1, 0.4, 12).finished();
  Matrix3d da_ = (Matrix3d() << 0.9, 0.1, 0, 0.2, 1.1, -0.3, 0, 0.05, 0.7).finished();
};

element::CableSection section() {
  element::CableSection s;
  s.area = 1e-3;
  s.density = 7850.0;
  s.material = std::make_shared<material::LinearElasticCable>(2e9, material::Compression::Carry);
  s.axial_damping = 2.5e4;
  return s;
}

// A curved element of N nodes, stretched and moving (the fields of line_damping_test.cpp).
void curvedElement(int n, model::NodalField& X, model::State& state) {
  X.resize(3, n);
  state = model::State(n);
  for (int i = 0; i < n; ++i) {
    const double s = 2.0 * i / (n - 1);
    X.col(i) = Vector3d(s, 0.3 * std::sin(s), 0.1 * s * s);
    state.displacement.col(i) = 0.01 * X.col(i) + 0.002 * Vector3d(std::cos(s), s, -s * s);
    state.velocity.col(i) = Vector3d(0.4 - 0.3 * s, 0.25 * std::cos(4.0 * s), -0.1 + 0.5 * s);
    state.acceleration.col(i) = Vector3d(0.2 * s, -0.1, 0.3 * std::sin(s));
  }
}

TEST(SummedLoadMatrices, CableLineLoadAndDamping) {
  const LinearLineLoad load;
  for (int n : {2, 3, 4}) {
    model::NodalField X;
    model::State state;
    curvedElement(n, X, state);
    std::vector<int> nodes(n);
    for (int i = 0; i < n; ++i) nodes[i] = i;
    const auto e = element::makeCableElement(nodes, section());
    VectorXd p;
    const double line_error = summedError([&](element::LoadMatrices& J) {
      ASSERT_TRUE(e->lineLoad({X, state, 0}, load, p, &J));
    });
    const double damping_error = summedError([&](element::LoadMatrices& J) {
      e->dampingForce({X, state, 0}, p, &J);
    });
    std::cout << n << " nodes: line load " << line_error << ", damping " << damping_error << "\n";
    EXPECT_LT(line_error, 2e-15) << n << " nodes";
    EXPECT_LT(damping_error, 2e-15) << n << " nodes";
  }
}

TEST(SummedLoadMatrices, Dashpot) {
  const test::ObliqueDashpot d;
  const model::NodalField& X = d.X;
  const element::SpringElement& e = d.element;
  const model::State& state = d.state;
  VectorXd f;
  const double error = summedError([&](element::LoadMatrices& J) {
    e.dampingForce({X, state, 0}, f, &J);
  });
  std::cout << "dashpot " << error << "\n";
  EXPECT_LT(error, 2e-15);
}

}  // namespace
}  // namespace flexmoor::test
