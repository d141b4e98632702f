#include "libstruct/solve/equilibrium.hpp"

namespace flexmoor::solve {

Residual outOfBalance(const model::Assembler& assembler, const model::State& state,
                      model::SparseMatrix* K) {
  Eigen::VectorXd F, P;
  assembler.internalForce(state, F, K);
  assembler.externalLoad(state, P);
  Residual r;
  r.free = assembler.restrictToFree(P - F);
  r.scale = std::max(P.norm(), F.norm());
  return r;
}

double displacementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                        const model::NodalField& u) {
  const double u_norm = assembler.restrictToFree(asVector(u)).norm();
  return u_norm > 0.0 ? du.norm() / u_norm : du.norm();
}

}  // namespace flexmoor::solve
