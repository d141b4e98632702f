#pragma once
// The pieces every implicit solver shares: the out-of-balance force of a state and the norms of
// Eq. 5.1.
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct Residual {
  Eigen::VectorXd free;  // P - F on the free dofs
  double scale = 0.0;    // max(|P|, |F|) over all dofs, reactions included
  // What round-off leaves of |R|, relative to `scale` (0 when no tangent was assembled): a
  // position is known to eps |x|, which a stiffness K_ii turns into a force eps |x| K_ii; over
  // n free dofs, eps rms|x| max(K_ii) sqrt(n). Long, stiff, finely meshed cables reach it well
  // above a residual tolerance of 1e-8 (a 10,000-element steel chain: about 5e-7).
  double floor = 0.0;
  double relative() const { return scale > 0.0 ? free.norm() / scale : free.norm(); }
};

// R = P - F at the state; fills the tangent and the round-off floor when K is given, and the
// motion-dependent loads' matrices when J is (from the same evaluation of the loads).
Residual outOfBalance(const model::Assembler& assembler, const model::State& state,
                      model::SparseMatrix* K, model::LoadMatrices* J = nullptr);
// The same into `r`, with the full force vectors in `scratch`: storage that is reused, so an
// iteration of a time step allocates nothing.
struct BalanceScratch {
  Eigen::VectorXd internal, external, difference;
};
void outOfBalance(const model::Assembler& assembler, const model::State& state,
                  model::SparseMatrix* K, model::LoadMatrices* J, BalanceScratch& scratch,
                  Residual& r);

// outOfBalance for a static or relaxation solve: with K, the static tangent, K_T plus the
// motion-dependent loads' stiffness -dP/du (load_point.hpp), from the same evaluation of the
// loads (nothing added for a model without them). Such a solve needs it where a load of that kind
// is all that holds a dof (a line lying on the seabed, a buoy on its buoyancy). It makes the
// tangent non-symmetric: solve with LU. The round-off floor is that of K_T.
Residual staticOutOfBalance(const model::Assembler& assembler, const model::State& state,
                            model::SparseMatrix* K);

// A round-off floor above this means the coordinates have run away (a mechanism under load
// pushed to 1e10 m makes the floor 5): the residual test then still asks for this much, so such a
// state is never taken for an equilibrium. Real floors stay far below (5e-7 for a 10,000-element
// steel chain).
inline constexpr double kFloorLimit = 1e-4;

// Eq. 5.1 and/or the residual test, as the options ask; the residual test never asks for less
// than the round-off floor allows, up to kFloorLimit.
bool converged(const Convergence& c, double displacement_norm, double residual_norm,
               double residual_floor);

// Eq. 5.1: sqrt(sum du^2 / sum u^2) over the free dofs (|du| when u vanishes).
double displacementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                        const model::NodalField& u);

// A static or relaxation step finds the structure at rest: every dof's velocity and
// acceleration are set to zero, a moving support's too (its history gives its place at the
// state's time, not a rate: a fairlead on a moving platform must not drag viscous forces into
// the statics), and the motion record is cleared. Called after applyPrescribed.
void putAtRest(model::State& state);

// Displacement of all dofs as one full vector (3 * node + component).
inline Eigen::Map<const Eigen::VectorXd> asVector(const model::NodalField& field) {
  return Eigen::Map<const Eigen::VectorXd>(field.data(), field.size());
}

}  // namespace flexmoor::solve
