#include "libstruct/solve/bfgs.hpp"

namespace flexmoor::solve {

void BfgsUpdates::add(const Eigen::VectorXd& s, const Eigen::VectorXd& y) {
  const double ys = y.dot(s);
  if (ys > 1e-14 * y.norm() * s.norm()) pairs_.push_back({s, y, 1.0 / ys});
}

Eigen::VectorXd BfgsUpdates::apply(const Eigen::VectorXd& R, const LinearSolver& K0) const {
  Eigen::VectorXd q = R;
  std::vector<double> alpha(pairs_.size());
  for (int i = static_cast<int>(pairs_.size()) - 1; i >= 0; --i) {
    alpha[i] = pairs_[i].rho * pairs_[i].s.dot(q);
    q -= alpha[i] * pairs_[i].y;
  }
  Eigen::VectorXd r = K0.solve(q);
  for (size_t i = 0; i < pairs_.size(); ++i) {
    const double beta = pairs_[i].rho * pairs_[i].y.dot(r);
    r += (alpha[i] - beta) * pairs_[i].s;
  }
  return r;
}

}  // namespace flexmoor::solve
