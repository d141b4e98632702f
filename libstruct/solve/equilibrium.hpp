#pragma once
// The pieces every implicit solver shares: the out-of-balance force of a state and the norms of
// Eq. 5.1.
#include "libstruct/model/assembler.hpp"

namespace flexmoor::solve {

struct Residual {
  Eigen::VectorXd free;  // P - F on the free dofs
  double scale = 0.0;    // max(|P|, |F|) over all dofs, reactions included
  double relative() const { return scale > 0.0 ? free.norm() / scale : free.norm(); }
};

// R = P - F at the state; fills the tangent when K is given.
Residual outOfBalance(const model::Assembler& assembler, const model::State& state,
                      model::SparseMatrix* K);

// Eq. 5.1: sqrt(sum du^2 / sum u^2) over the free dofs (|du| when u vanishes).
double displacementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                        const model::NodalField& u);

// Displacement of all dofs as one full vector (3 * node + component).
inline Eigen::Map<const Eigen::VectorXd> asVector(const model::NodalField& field) {
  return Eigen::Map<const Eigen::VectorXd>(field.data(), field.size());
}

}  // namespace flexmoor::solve
