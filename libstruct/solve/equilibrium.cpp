#include "libstruct/solve/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexmoor::solve {

Residual outOfBalance(const model::Assembler& assembler, const model::State& state,
                      model::SparseMatrix* K, model::LoadMatrices* J) {
  BalanceScratch scratch;
  Residual r;
  outOfBalance(assembler, state, K, J, scratch, r);
  return r;
}

void outOfBalance(const model::Assembler& assembler, const model::State& state,
                  model::SparseMatrix* K, model::LoadMatrices* J, BalanceScratch& scratch,
                  Residual& r) {
  Eigen::VectorXd &F = scratch.internal, &P = scratch.external;
  assembler.internalForce(state, F, K);
  assembler.externalLoad(state, P, J);
  scratch.difference = P - F;
  assembler.restrictToFree(scratch.difference, r.free);
  r.scale = std::max(P.norm(), F.norm());
  r.floor = 0.0;
  if (K && K->rows() > 0 && r.scale > 0.0) {
    const auto x = assembler.model().reference() + state.displacement;  // not materialised
    const double rms = std::sqrt(x.squaredNorm() / std::max<Eigen::Index>(x.size(), 1));
    const double k = K->diagonal().cwiseAbs().maxCoeff();
    r.floor = std::numeric_limits<double>::epsilon() * rms * k *
              std::sqrt(static_cast<double>(K->rows())) / r.scale;
  }
}

Residual staticOutOfBalance(const model::Assembler& assembler, const model::State& state,
                            model::SparseMatrix* K) {
  if (!K || !assembler.model().hasMotionLoads()) return outOfBalance(assembler, state, K);
  model::LoadMatrices J;
  const Residual r = outOfBalance(assembler, state, K, &J);
  K->coeffs() += J.stiffness.coeffs();
  return r;
}

bool converged(const Convergence& c, double displacement_norm, double residual_norm,
               double residual_floor) {
  const bool displacement_ok = !c.use_displacement || displacement_norm < c.displacement_tolerance;
  const bool residual_ok =
      !c.use_residual ||
      residual_norm < std::max(c.residual_tolerance, std::min(residual_floor, kFloorLimit));
  return displacement_ok && residual_ok;
}

double displacementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                        const model::NodalField& u) {
  const double u_norm = assembler.restrictToFree(asVector(u)).norm();
  return u_norm > 0.0 ? du.norm() / u_norm : du.norm();
}

void putAtRest(model::State& state) {
  state.velocity.setZero();
  state.acceleration.setZero();
  state.motion = {};
}

}  // namespace flexmoor::solve
