#pragma once
// The element mass matrix from its scalar mass matrix m_IJ = integral rho h M^I M^J dA (Eq. 4.40,
// 4.49): the same m on each of the three translations of a node, consistent or lumped. One kernel
// for every element.
#include <Eigen/Core>

#include "libstruct/element/element.hpp"

namespace flexmoor::element {

// Lumping: row sums would give negative masses at the corners of higher orders, so the diagonal
// is scaled to keep the element's total instead (HRZ lumping). Positive at every node.
template <int N>
Eigen::Matrix<double, N, 1> lumpedDiagonal(const Eigen::Matrix<double, N, N>& m) {
  return m.diagonal() * (m.sum() / m.diagonal().sum());
}

template <int N>
void nodalMass(const Eigen::Matrix<double, N, N>& m, MassKind kind, Eigen::MatrixXd& M) {
  Eigen::Matrix<double, N, N> used = m;
  if (kind == MassKind::Lumped) used = lumpedDiagonal<N>(m).asDiagonal();
  M.setZero(3 * N, 3 * N);
  for (int I = 0; I < N; ++I)
    for (int J = 0; J < N; ++J)
      M.template block<3, 3>(3 * I, 3 * J).diagonal().setConstant(used(I, J));
}

}  // namespace flexmoor::element
