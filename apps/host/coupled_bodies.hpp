#pragma once
// The rigid bodies of a case that a host program drives (Case::rigid_motions: a spread mooring's
// `platform`, the rigid_motion histories of a case). Each body has six coupled dofs: the
// translation of its reference point from where the case puts it at rest (surge, sway, heave, in
// the case's length unit) and its rotations roll, pitch, yaw (rad), R = Rz(yaw) Ry(pitch) Rx(roll)
// (libstruct/model/rigid_body_motion.hpp). The host gives their values, rates and, if it knows
// them, accelerations at the end of each of its steps; in between they follow the Hermite
// interpolant of the two ends (libstruct/model/coupled_motion.hpp). Back come the lines' loads on
// each body: the force and the moment about its reference point where it is.
#include <string>
#include <vector>

#include "apps/problem/case.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/coupled_motion.hpp"

namespace flexmoor::app {

// "platform, ..." or "none": the rigid motions of `c` a host may couple, for messages.
std::string rigidMotionNames(const Case& c);

class CoupledBodies {
 public:
  static constexpr int kDofs = 6;  // per body

  // Takes the rigid motions `names` of `c` over, in that order; std::invalid_argument naming the
  // case's rigid motions when one is not among them or is named twice. Must come before the
  // simulation of `c` is prepared; `c` must outlive it.
  CoupledBodies(const Case& c, const std::vector<std::string>& names);

  int dofs() const { return kDofs * static_cast<int>(bodies_.size()); }

  // At rest at time t in the states x, xd and xdd (dofs() values each; xdd may be null: zero),
  // where the statics find them: the start.
  void hold(double t, const double* x, const double* xd, const double* xdd);
  // The host's next step ends at time t in these states (xdd null: not known).
  void next(double t, const double* x, const double* xd, const double* xdd);

  // The lines' loads on the bodies at state s, dofs() values: for each body the force (x, y, z)
  // and the moment about its reference point (x, y, z), minus the sum of the support reactions
  // at the nodes it carries (assembler.hpp: internal and damping forces less the loads there,
  // without the inertia of the line mass lumped at those nodes).
  void loads(const model::State& s, const model::Assembler& assembler, double* f) const;

  // The coupled motions' states, to put back with restore().
  std::vector<model::CoupledMotion::Sample> save() const;
  void restore(const std::vector<model::CoupledMotion::Sample>& samples);

 private:
  struct Point {
    int node;
    Eigen::Vector3d arm;  // from the body's reference point at rest
  };
  struct Body {
    std::shared_ptr<model::RigidBodyMotion> motion;
    std::array<std::shared_ptr<model::CoupledMotion>, kDofs> dofs;
    std::vector<Point> points;
  };
  std::vector<Body> bodies_;
  mutable model::NodalField reactions_;
};

}  // namespace flexmoor::app
