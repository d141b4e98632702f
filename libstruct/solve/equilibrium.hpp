#pragma once
// The pieces every implicit solver shares: the out-of-balance force of a state and the norms of
// Eq. 5.1.
#include <cmath>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::solve {

struct Residual {
  Eigen::VectorXd free;  // P - F on the free dofs
  double scale = 0.0;    // max(|P|, |F|, lambda |W|) over all dofs, reactions included
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

// The largest residual, relative to the forces in play, that any solver accepts as an
// equilibrium, whatever its criterion (a displacement test alone, the self-corrective scheme's
// single solve): a state further out of balance is an error, never a result.
inline constexpr double kAcceptedResidual = 1e-2;

// The norms of one Newton iterate (Convergence): the increment's largest component over the
// model's element size and what round-off leaves of it, the residual over the forces in play and
// what round-off leaves of it.
struct IterateNorms {
  double displacement = 0.0;
  double displacement_floor = 0.0;
  double residual = 0.0;
  double residual_floor = 0.0;
};

// The Convergence test: the residual and/or displacement test, as the options ask, each never
// asking for less than round-off allows (the residual's floor up to kFloorLimit), and the
// residual within kAcceptedResidual in any case.
bool converged(const Convergence& c, const IterateNorms& norms);
// The residual alone against kAcceptedResidual (and its floor): what a state must meet to be
// reported as an equilibrium at all.
bool acceptable(double residual_norm, double residual_floor);

// The increment's norm for Convergence: max |du_i| / L over the free dofs, L the model's element
// size; with its round-off floor, 8 eps max |x_i| / L, x the current coordinates.
void incrementNorm(const model::Assembler& assembler, const Eigen::VectorXd& du,
                   const model::NodalField& u, IterateNorms& norms);

// Backtracking, the line search of the Newton loops: a Newton increment after the first that
// raised the residual (or made it non-finite) is halved, up to kMaxBacktracks times in a row,
// before Newton goes on from there. A kink in the loads (a point of a line touching the seabed,
// a slack line) otherwise makes full Newton cycle between the two sides of it.
class Backtracking {
 public:
  static constexpr int kMaxBacktracks = 4;
  // Called with the residual of iterate `it` (0: before the first increment): true when the
  // increment that led there should be halved.
  bool halve(int it, double residual) {
    const bool worse = !std::isfinite(residual) || residual > previous_;
    if (it >= 2 && worse && halvings_ < kMaxBacktracks) {
      ++halvings_;
      return true;
    }
    halvings_ = 0;
    previous_ = residual;
    return false;
  }

 private:
  double previous_ = 0.0;
  int halvings_ = 0;
};

// A static or relaxation step finds the structure at rest: every dof's velocity and
// acceleration are set to zero, a moving support's too (its history gives its place at the
// state's time, not a rate: a fairlead on a moving platform must not drag viscous forces into
// the statics), and the motion record is cleared. Called after applyPrescribed.
// The loads of a static solve see still water (State::still) unless `frozen_waves`: then the
// waves as they stand at the state's time.
void putAtRest(model::State& state, bool frozen_waves);

// Displacement of all dofs as one full vector (3 * node + component).
inline Eigen::Map<const Eigen::VectorXd> asVector(const model::NodalField& field) {
  return Eigen::Map<const Eigen::VectorXd>(field.data(), field.size());
}

}  // namespace flexmoor::solve
