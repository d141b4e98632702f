#pragma once
// The Jacobian of an element's map from natural coordinates to its reference geometry, the test
// that the map is one to one: it must be positive at every integration point. One kernel for the
// line elements (cables, axisymmetric meridians) and one for the surfaces (membranes); each
// returns the smallest Jacobian relative to that of a regular element of the same size (the
// diagonal D of the nodes' bounding box: D / 2 for a line, (D / 2)^2 for a surface), so that
// "degenerate" does not depend on the model's units. It is of order 1 for a well-shaped element
// and <= 0 for a folded, inverted or collapsed one.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "libstruct/shape/lagrange_1d.hpp"

namespace flexmoor::element {

template <int N>
double boundingDiagonal(const Eigen::Matrix<double, 3, N>& X) {
  return (X.rowwise().maxCoeff() - X.rowwise().minCoeff()).norm();
}

// A line of N nodes: dX/dxi projected on the chord e = (X_N - X_1) / |X_N - X_1|, at the points
// xi. A middle node that coincides with an end, or lies beyond the other, folds the line back on
// itself: dX/dxi . e changes sign along the element even where |dX/dxi| does not vanish.
template <int N>
double lineRelativeJacobian(const Eigen::Matrix<double, 3, N>& X, const std::vector<double>& xi) {
  const Eigen::Vector3d chord = X.col(N - 1) - X.col(0);
  const double size = boundingDiagonal<N>(X);
  if (!(chord.norm() > 0.0) || !(size > 0.0)) return 0.0;
  const Eigen::Vector3d e = chord / chord.norm();
  double smallest = std::numeric_limits<double>::infinity();
  for (double p : xi)
    smallest = std::min(smallest, (X * shape::Lagrange1D<N>::derivatives(p)).dot(e));
  return smallest / (size / 2.0);
}

// A surface of shape Shape (QuadShape or TriangleShape): the signed area element
// (X,1 x X,2) . n at the points, n the element's mean normal (the integral of X,1 x X,2 over the
// points, normalised). A bow-tie quadrilateral has X,1 x X,2 of both signs about n; a collapsed
// one has no mean normal at all.
template <class Shape, int N>
double surfaceRelativeJacobian(const Eigen::Matrix<double, 3, N>& X,
                               const std::vector<Eigen::Vector2d>& points) {
  std::vector<Eigen::Vector3d> area(points.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t q = 0; q < points.size(); ++q) {
    const Eigen::Matrix<double, 3, 2> x = X * Shape::derivatives(points[q].x(), points[q].y());
    area[q] = x.col(0).cross(x.col(1));
    mean += area[q];
  }
  const double scale = std::pow(boundingDiagonal<N>(X) / 2.0, 2);
  if (!(mean.norm() > 0.0) || !(scale > 0.0)) return 0.0;
  const Eigen::Vector3d n = mean / mean.norm();
  double smallest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& a : area) smallest = std::min(smallest, a.dot(n));
  return smallest / scale;
}

}  // namespace flexmoor::element
