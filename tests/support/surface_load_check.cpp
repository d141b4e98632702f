#include "tests/support/surface_load_check.hpp"

namespace flexmoor::test {

double surfaceStiffnessError(const element::Element& e, const model::NodalField& X,
                             const model::State& s, const model::SurfaceLoad& load) {
  Eigen::VectorXd f, plus, minus;
  element::LoadMatrices J;
  e.surfaceLoad({X, s, 0}, load, f, &J);
  Eigen::MatrixXd numeric(J.stiffness.rows(), J.stiffness.cols());
  const double h = 1e-6;
  for (int j = 0; j < numeric.cols(); ++j) {
    model::State sp = s, sm = s;
    sp.displacement.data()[j] += h;
    sm.displacement.data()[j] -= h;
    e.surfaceLoad({X, sp, 0}, load, plus, nullptr);
    e.surfaceLoad({X, sm, 0}, load, minus, nullptr);
    numeric.col(j) = -(plus - minus) / (2.0 * h);
  }
  return (J.stiffness - numeric).cwiseAbs().maxCoeff() / J.stiffness.cwiseAbs().maxCoeff();
}

}  // namespace flexmoor::test
