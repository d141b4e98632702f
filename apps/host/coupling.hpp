#pragma once
// What a host program drives in a case, step by step: rigid bodies and points.
// - A body (Case::rigid_motions: a spread mooring's `platform`, the rigid_motion histories of a
//   case) has six coupled dofs: the translation of its reference point from where the case puts
//   it at rest (surge, sway, heave, in the case's length unit) and its rotations roll, pitch, yaw
//   (rad), R = Rz(yaw) Ry(pitch) Rx(roll) (libstruct/model/rigid_body_motion.hpp). Its loads: the
//   lines' force on it and their moment about its reference point where it is.
// - A point (a line's end: LINE.fairlead, LINE.anchor, LINE.start, LINE.end), held in x, y and z
//   by the case's supports, has three: its position x, y, z in the case's frame and length unit
//   (as MoorDyn's coupled points). The host's motion replaces whatever the supports prescribed.
//   Its loads: the lines' force on it.
// The host gives the values, rates and, if it knows them, accelerations at the end of each of
// its steps; in between they follow the Hermite interpolant of the two ends
// (libstruct/model/coupled_motion.hpp). The coupled dofs and the loads are in the order the
// objects were named.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "apps/problem/case.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/coupled_motion.hpp"

namespace flexmoor::app {

// "platform, ..." or "none": the rigid motions of `c` a host may couple, for messages.
std::string rigidMotionNames(const Case& c);

class Coupling {
 public:
  static constexpr int kBodyDofs = 6;
  static constexpr int kPointDofs = 3;

  // The coupled dofs of each of the bodies and points `names` of `c` (kBodyDofs or kPointDofs);
  // std::invalid_argument saying why when one is not there, is named twice, or is a point one of
  // the bodies carries.
  static std::vector<int> dofsOf(const Case& c, const std::vector<std::string>& names);

  // Takes the bodies and points `names` of `c` over, in that order (std::invalid_argument as
  // dofsOf). Must come before the simulation of `c` is prepared; `c` must outlive it.
  Coupling(const Case& c, const std::vector<std::string>& names);

  int dofs() const { return static_cast<int>(dofs_.size()); }

  // At rest at time t in the states x, xd and xdd (dofs() values each; xdd may be null: zero),
  // where the statics find them: the start.
  void hold(double t, const double* x, const double* xd, const double* xdd);
  // The host's next step ends at time t in these states (xdd null: not known).
  void next(double t, const double* x, const double* xd, const double* xdd);

  // The lines' loads on what is coupled at state s, dofs() values: for a body the force (x, y, z)
  // and the moment about its reference point (x, y, z), minus the sum of the support reactions at
  // the nodes it carries; for a point the force, minus its reaction (assembler.hpp: internal and
  // damping forces less the loads there, without the inertia of the line mass lumped there).
  void loads(const model::State& s, const model::Assembler& assembler, double* f) const;

  // The coupled motions' states, to put back with restore().
  std::vector<model::CoupledMotion::Sample> save() const;
  void restore(const std::vector<model::CoupledMotion::Sample>& samples);

 private:
  struct Carried {
    int node;
    Eigen::Vector3d arm;  // from the body's reference point at rest
  };
  struct Body {
    std::shared_ptr<model::RigidBodyMotion> motion;
    std::vector<Carried> points;
    int first_dof;
  };
  struct Point {
    int node;
    int first_dof;
  };
  // A coupled dof's motion, and what turns the host's value into it: the dof's reference
  // position, subtracted (a point's coordinate), or 0 (a body's dof).
  struct Dof {
    std::shared_ptr<model::CoupledMotion> motion;
    double offset;
  };
  static std::vector<Carried> carried(const model::Model& m, const model::RigidBodyMotion& body);
  // For each name, the node of a point (-1 for a body) and the nodes a body carries.
  struct Resolved {
    std::vector<int> point_nodes;
    std::vector<std::vector<Carried>> carried_by;
  };
  static Resolved resolve(const Case& c, const std::vector<std::string>& names);
  model::CoupledMotion::Sample sample(double t, const double* x, const double* xd,
                                      const double* xdd, int k) const;

  std::vector<Body> bodies_;
  std::vector<Point> points_;
  std::vector<Dof> dofs_;
  mutable model::NodalField reactions_;
};

}  // namespace flexmoor::app
