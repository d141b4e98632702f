#include "apps/output/membrane_resultants.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace flexmoor::app {

namespace {

// The two principal values of a tensor n that lies in a plane (rank 2 at most), larger first.
// The plane's normal is the cross product of two rows of n (each row lies in the plane); in an
// orthonormal basis (e1, e2) of the plane the 2 x 2 tensor's eigenvalues are m +- r with
// m = (b11 + b22) / 2 and r = hypot((b11 - b22) / 2, b12), free of cancellation. When the rows
// are (nearly) parallel, a uniaxial or zero tensor, the normal is not defined by them and the
// general symmetric eigensolver gives the two values of largest magnitude.
std::pair<double, double> inPlanePrincipal(const Eigen::Matrix3d& n) {
  const Eigen::Vector3d c[3] = {n.row(0).cross(n.row(1)), n.row(1).cross(n.row(2)),
                                n.row(2).cross(n.row(0))};
  const int k = std::max_element(c, c + 3,
                                 [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
                                   return a.squaredNorm() < b.squaredNorm();
                                 }) -
                c;
  const double scale = n.squaredNorm();
  if (c[k].squaredNorm() > 1e-10 * scale * scale) {  // smaller / larger > 1e-5
    const Eigen::Vector3d normal = c[k].normalized();
    const Eigen::Vector3d e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    const double b11 = e1.dot(n * e1), b22 = e2.dot(n * e2), b12 = e1.dot(n * e2);
    const double m = 0.5 * (b11 + b22), r = std::hypot(0.5 * (b11 - b22), b12);
    return {m + r, m - r};
  }
  Eigen::Vector3d values =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(n, Eigen::EigenvaluesOnly).eigenvalues();
  std::sort(values.data(), values.data() + 3,
            [](double a, double b) { return std::abs(a) > std::abs(b); });
  return {std::max(values(0), values(1)), std::min(values(0), values(1))};
}

}  // namespace

// The in-plane principal resultants at each integration point, averaged over the points. Each
// point's tensor lies in that point's tangent plane: of its three eigenvalues, the one along the
// surface normal is zero; the other two are the principal resultants. (Averaging the tensors
// first would mix tangent planes of different orientation: on a curved element, a Q8 spanning 45
// degrees of a tube, the hoop resultant came out 6% low.)
std::optional<std::pair<double, double>> principalResultants(const element::ElementResult& r) {
  if (r.point_resultant.empty()) return std::nullopt;
  double larger = 0.0, smaller = 0.0;
  for (const Eigen::Matrix3d& n : r.point_resultant) {
    const auto [first, second] = inPlanePrincipal(n);
    larger += first;
    smaller += second;
  }
  const double count = static_cast<double>(r.point_resultant.size());
  return std::pair(larger / count, smaller / count);
}

}  // namespace flexmoor::app
