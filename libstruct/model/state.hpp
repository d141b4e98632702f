#pragma once
// The nodal state of a model: reference coordinates X and the kinematic fields u, u', u''
// (3 x number of nodes each), plus the time and the load factor the state belongs to.
#include <Eigen/Core>

namespace flexmoor::model {

using NodalField = Eigen::Matrix3Xd;

// What a time integration leaves in the state for the next one to continue from. A dynamic step
// that follows another with the same load factor and the same equation of motion (mass, damping,
// HHT alpha) continues from the accepted u'' instead of solving for it again, so that a run split
// into several steps gives the one-step result to round-off. Whatever else moves the state (a
// static or relaxation step) clears it, and the next integration starts from equilibrium.
struct MotionRecord {
  bool valid = false;        // u'' is that of an accepted time step
  double load_factor = 0.0;  // the load factor it was accepted at
  int mass_kind = 0;         // element::MassKind, as an int
  double rayleigh_mass = 0.0;
  double rayleigh_stiffness = 0.0;
  double hht_alpha = 0.0;
  double force_scale = 0.0;  // the largest force norm seen so far (the residual test's scale)
};

struct State {
  NodalField displacement;
  NodalField velocity;
  NodalField acceleration;
  double time = 0.0;
  double load_factor = 0.0;
  MotionRecord motion;

  explicit State(int node_count = 0)
      : displacement(NodalField::Zero(3, node_count)),
        velocity(NodalField::Zero(3, node_count)),
        acceleration(NodalField::Zero(3, node_count)) {}
};

// Whether two states have the same displacements (exactly: what the internal force depends on).
inline bool sameDisplacement(const State& a, const State& b) {
  return a.displacement.cols() == b.displacement.cols() && a.displacement == b.displacement;
}

// Whether two states are the same for every force: displacement, velocity, acceleration, time and
// load factor equal, exactly (the motion record aside).
inline bool sameState(const State& a, const State& b) {
  return sameDisplacement(a, b) && a.time == b.time && a.load_factor == b.load_factor &&
         a.velocity == b.velocity && a.acceleration == b.acceleration;
}

}  // namespace flexmoor::model
