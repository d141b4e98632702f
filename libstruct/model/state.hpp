#pragma once
// The nodal state of a model: reference coordinates X and the kinematic fields u, u', u''
// (3 x number of nodes each), plus the time and the load factor the state belongs to.
#include <Eigen/Core>
#include <cstddef>
#include <cstring>

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
  // The state of a static solve (putAtRest): the loads see still water, no waves (LoadPoint).
  bool still = false;
  MotionRecord motion;

  explicit State(int node_count = 0)
      : displacement(NodalField::Zero(3, node_count)),
        velocity(NodalField::Zero(3, node_count)),
        acceleration(NodalField::Zero(3, node_count)) {}
};

// Whether two fields hold the same values bit for bit (one memcmp: a record asks it of some 100
// values, and a coefficient-wise == took 70 ns there). A 0 that became -0 counts as a change,
// which only costs a memo its use.
inline bool sameBits(const NodalField& a, const NodalField& b) {
  return a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

// Whether two states have the same displacements (exactly: what the internal force depends on).
inline bool sameDisplacement(const State& a, const State& b) {
  return sameBits(a.displacement, b.displacement);
}

// Whether two states are the same for every force: displacement, velocity, acceleration, time and
// load factor equal, exactly (the motion record aside).
inline bool sameState(const State& a, const State& b) {
  return sameDisplacement(a, b) && a.time == b.time && a.load_factor == b.load_factor &&
         a.still == b.still && sameBits(a.velocity, b.velocity) &&
         sameBits(a.acceleration, b.acceleration);
}

}  // namespace flexmoor::model
