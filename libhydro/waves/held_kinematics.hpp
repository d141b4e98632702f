#pragma once
// A shortcut for the loads' kinematics within a time step: at one time t, the first
// query near a point evaluates the sea there with its gradient (Sea::at); a later query at the
// same t within `radius` of it, and on the same side of the surface, is its first-order Taylor
// expansion, value + gradient . dx (the elevation, velocity, acceleration and pressure; the
// gradient is the held one). A Newton iteration moves a line's points by millimetres to
// centimetres, so a time step's iterations cost one evaluation a point instead of one each; the
// error is of order (k dx)^2 of the component of wave number k (measured in docs/performance.md).
// A new t forgets what was held. Points are grouped by a key (the element), so that a lookup
// scans only its group (at most 64 points; a fuller group starts afresh). Safe to share between
// threads (a lock), though one model evaluates its loads on one thread.
#include <Eigen/Core>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "libhydro/waves/sea.hpp"

namespace flexmoor::hydro {

class HeldKinematics {
 public:
  HeldKinematics(std::shared_ptr<const Sea> sea, double radius);  // radius > 0

  // The flow at x, t and its gradient: exact on a miss, Taylor-expanded on a hit.
  FluidPoint at(int key, const Eigen::Vector3d& x, double t, FluidGradient& gradient) const;

  struct Counts {
    long evaluations = 0;  // Sea::at calls
    long reuses = 0;       // queries answered from what was held
  };
  Counts counts() const;
  const Sea& sea() const { return *sea_; }

 private:
  struct Held {
    Eigen::Vector3d x;
    FluidPoint flow;
    FluidGradient gradient;
  };
  std::shared_ptr<const Sea> sea_;
  double radius_;
  mutable std::mutex lock_;
  mutable bool any_ = false;
  mutable double t_ = 0.0;
  mutable std::unordered_map<int, std::vector<Held>> held_;
  mutable Counts counts_;
};

}  // namespace flexmoor::hydro
