// The one Newton loop of every solver (newtonSolve) on small systems whose solutions are known:
// quadratic convergence, acceptance only at a measured residual, backtracking where full Newton
// diverges, the self-corrective single solve, and the failures it reports.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "libstruct/model/model.hpp"
#include "libstruct/solve/newton.hpp"

namespace flexmoor::test {
namespace {

using Eigen::VectorXd;

// R(x) = b - f(x) with its Jacobian df/dx, on plain vectors; the norm relative to |b|.
class SmallSystem final : public solve::NewtonProblem {
 public:
  SmallSystem(std::function<VectorXd(const VectorXd&)> f,
              std::function<Eigen::MatrixXd(const VectorXd&)> jacobian, VectorXd b, VectorXd x0)
      : f_(std::move(f)), jacobian_(std::move(jacobian)), b_(std::move(b)), x(std::move(x0)) {}

  void evaluate(int, VectorXd& R, solve::IterateNorms& norms) override {
    R = b_ - f_(x);
    norms.residual = R.norm() / b_.norm();
    norms.residual_floor = 0.0;
    residuals.push_back(norms.residual);
  }
  bool accepts(const solve::IterateNorms& norms) const override {
    return single ? solve::acceptable(norms.residual, norms.residual_floor)
                  : solve::converged(convergence, norms);
  }
  bool increment(int, const VectorXd& R, VectorXd& du) override {
    if (refuse) return false;
    du = jacobian_(x).fullPivLu().solve(R);
    return true;
  }
  void add(const VectorXd& du, double scale) override { x += scale * du; }
  void measure(const VectorXd& du, solve::IterateNorms& norms) const override {
    norms.displacement = du.cwiseAbs().maxCoeff();
    norms.displacement_floor = 0.0;
  }

  std::function<VectorXd(const VectorXd&)> f_;
  std::function<Eigen::MatrixXd(const VectorXd&)> jacobian_;
  VectorXd b_;
  VectorXd x;
  solve::Convergence convergence;
  bool single = false, refuse = false;
  std::vector<double> residuals;  // of every evaluation, in order
};

// f(x) = (x0^3 + x1, x1^3 - x0) = (10, 6) at x = (2, 2).
SmallSystem cubic(VectorXd x0) {
  return SmallSystem(
      [](const VectorXd& x) {
        VectorXd f(2);
        f << x(0) * x(0) * x(0) + x(1), x(1) * x(1) * x(1) - x(0);
        return f;
      },
      [](const VectorXd& x) {
        Eigen::MatrixXd J(2, 2);
        J << 3.0 * x(0) * x(0), 1.0, -1.0, 3.0 * x(1) * x(1);
        return J;
      },
      (VectorXd(2) << 10.0, 6.0).finished(), std::move(x0));
}

// f(x) = atan(x) = 0: full Newton from |x0| > 1.39 overshoots further every iteration.
SmallSystem arctangent(double x0) {
  return SmallSystem(
      [](const VectorXd& x) { return VectorXd(x.array().atan()); },
      [](const VectorXd& x) {
        return Eigen::MatrixXd((1.0 / (1.0 + x.array().square())).matrix().asDiagonal());
      },
      VectorXd::Constant(1, 1e-3), VectorXd::Constant(1, x0));
}

solve::NewtonOutcome run(SmallSystem& p, const solve::NewtonSettings& s) {
  const model::Model m;
  solve::NewtonTrace trace;
  solve::IterationRecord rec;
  return solve::newtonSolve(p, s, m, trace, rec);
}

// Quadratic convergence to (2, 2), accepted at an iterate whose residual was measured there and
// is below the tolerance: r_k+1 <= 0.5 r_k^2 once r_k < 1e-2, above round-off (measured: 0.476,
// 0.480; the constant is |b| |J^-1| |f''| / 2 at the solution).
TEST(NewtonLoop, ConvergesQuadraticallyAndAcceptsOnlyAMeasuredResidual) {
  SmallSystem p = cubic((VectorXd(2) << 3.0, 1.0).finished());
  const solve::NewtonOutcome out = run(p, {});
  ASSERT_TRUE(out.converged());
  EXPECT_NEAR(p.x(0), 2.0, 1e-12);
  EXPECT_NEAR(p.x(1), 2.0, 1e-12);
  EXPECT_LT(p.residuals.back(), p.convergence.residual_tolerance);
  EXPECT_EQ(static_cast<int>(p.residuals.size()), out.solves + 1);
  int quadratic = 0;
  for (std::size_t k = 0; k + 1 < p.residuals.size(); ++k)
    if (p.residuals[k] < 1e-2 && p.residuals[k + 1] > 1e-14) {
      EXPECT_LE(p.residuals[k + 1], 0.5 * p.residuals[k] * p.residuals[k]) << k;
      ++quadratic;
    }
  EXPECT_GE(quadratic, 2);
  EXPECT_EQ(out.backtracks, 0);
}

// atan(x) = 1e-3 from x0 = 1.5: without backtracking the iterates leave for infinity; with it,
// the increment that raised the residual is halved and Newton converges to tan(1e-3).
TEST(NewtonLoop, BacktrackingRescuesNewtonWhereItDiverges) {
  solve::NewtonSettings plain;
  plain.backtracking = false;
  SmallSystem diverging = arctangent(1.5);
  EXPECT_FALSE(run(diverging, plain).converged());
  EXPECT_GT(std::abs(diverging.x(0)), 1e3);

  SmallSystem rescued = arctangent(1.5);
  const solve::NewtonOutcome out = run(rescued, {});
  ASSERT_TRUE(out.converged());
  EXPECT_GE(out.backtracks, 1);
  EXPECT_NEAR(rescued.x(0), std::tan(1e-3), 1e-14);
}

// The self-corrective single solve: accepted while its residual is acceptable (below 1e-2 of
// the forces), not otherwise, and never a second solve.
TEST(NewtonLoop, SingleSolveIsAcceptedOnlyWhileItsResidualIsAcceptable) {
  solve::NewtonSettings single;
  single.single_solve = true;
  SmallSystem near = cubic((VectorXd(2) << 2.01, 1.99).finished());
  near.single = true;
  const solve::NewtonOutcome accepted = run(near, single);
  EXPECT_TRUE(accepted.converged());
  EXPECT_EQ(accepted.solves, 1);
  EXPECT_LT(near.residuals.back(), solve::kAcceptedResidual);

  SmallSystem far = cubic((VectorXd(2) << 6.0, -3.0).finished());
  far.single = true;
  const solve::NewtonOutcome refused = run(far, single);
  EXPECT_EQ(refused.result, solve::NewtonResult::NotConverged);
  EXPECT_EQ(refused.solves, 1);
  EXPECT_GT(far.residuals.back(), solve::kAcceptedResidual);
}

// Failures: no increment (a singular tangent) and a residual that is not finite are reported as
// such, with the iterate where they happened.
TEST(NewtonLoop, ReportsAMissingIncrementAndANonFiniteResidual) {
  SmallSystem singular = cubic((VectorXd(2) << 3.0, 1.0).finished());
  singular.refuse = true;
  EXPECT_EQ(run(singular, {}).result, solve::NewtonResult::NoIncrement);

  SmallSystem nan =
      cubic((VectorXd(2) << std::numeric_limits<double>::quiet_NaN(), 1.0).finished());
  EXPECT_EQ(run(nan, {}).result, solve::NewtonResult::NonFinite);
}

}  // namespace
}  // namespace flexmoor::test
