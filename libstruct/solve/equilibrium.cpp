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
  r.scale = std::max({P.norm(), F.norm(), std::abs(state.load_factor) * assembler.weightNorm()});
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

bool acceptable(double residual_norm, double residual_floor) {
  return residual_norm <= std::max(kAcceptedResidual, std::min(residual_floor, kFloorLimit));
}

bool converged(const Convergence& c, const IterateNorms& n) {
  const bool displacement_ok =
      !c.use_displacement ||
      n.displacement < std::max(c.displacement_tolerance, n.displacement_floor);
  const bool residual_ok =
      !c.use_residual ||
      n.residual < std::max(c.residual_tolerance, std::min(n.residual_floor, kFloorLimit));
  return displacement_ok && residual_ok && acceptable(n.residual, n.residual_floor);
}

void incrementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                   const model::NodalField& u, IterateNorms& norms) {
  const double L = assembler.elementSize();
  norms.displacement = du.size() > 0 ? du.cwiseAbs().maxCoeff() / L : 0.0;
  const auto x = assembler.model().reference() + u;  // not materialised
  const double largest = x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.0;
  norms.displacement_floor = 8.0 * std::numeric_limits<double>::epsilon() * largest / L;
}

void putAtRest(model::State& state, bool frozen_waves) {
  state.still = !frozen_waves;
  state.velocity.setZero();
  state.acceleration.setZero();
  state.motion = {};
}

}  // namespace flexmoor::solve
