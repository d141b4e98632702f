#include "apps/output/membrane_resultants.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace flexmoor::app {

// Of the mean tensor's three eigenvalues, the one along the surface normal is zero and the
// smallest in magnitude; the other two are the in-plane principal resultants.
std::optional<std::pair<double, double>> principalResultants(const element::ElementResult& r) {
  if (r.point_resultant.empty()) return std::nullopt;
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const Eigen::Matrix3d& n : r.point_resultant)
    mean += n / static_cast<double>(r.point_resultant.size());
  Eigen::Vector3d values = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(mean).eigenvalues();
  std::sort(values.data(), values.data() + 3,
            [](double a, double b) { return std::abs(a) > std::abs(b); });
  return std::pair(std::max(values(0), values(1)), std::min(values(0), values(1)));
}

}  // namespace flexmoor::app
