#pragma once
// The sea a structure sits in: still water, a list of linear wave components (a regular wave is
// one; an irregular sea adds more), an optional wave-train front, a current, and the treatment of
// the kinematics above the mean level. It answers what the loads need at a point and time: the
// surface elevation above it, whether the point is wet, the fluid velocity and local
// acceleration, and the gauge pressure (hydrostatic plus dynamic).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "libhydro/water/current_profile.hpp"
#include "libhydro/water/water.hpp"
#include "libhydro/waves/wave_component.hpp"
#include "libhydro/waves/wave_front.hpp"

namespace flexmoor::hydro {

// Linear theory holds below z = 0; between the mean level and the crest the kinematics are
// either Wheeler-stretched (evaluated at z' = h (z - eta) / (h + eta), the default) or taken as
// those at z = 0 (constant extrapolation). Above the surface everything is zero.
enum class SurfaceKinematics { Wheeler, ConstantAboveMean };

struct FluidPoint {
  double elevation = 0.0;                                  // eta above the point
  bool wet = false;                                        // z <= eta
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // waves + current
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // local, waves only
  double pressure = 0.0;                                   // gauge: -rho g z + p_dyn
};

class Sea {
 public:
  explicit Sea(Water water) : water_(water) {}

  void addComponent(const WaveComponent& c) { components_.push_back(c); }
  void setFront(const WaveFront& front) { front_ = front; }
  void setCurrent(const CurrentProfile& current) { current_ = current; }
  void setSurfaceKinematics(SurfaceKinematics k) { surface_ = k; }

  const Water& water() const { return water_; }
  const std::vector<WaveComponent>& components() const { return components_; }

  double elevation(const Eigen::Vector3d& x, double t) const;
  FluidPoint at(const Eigen::Vector3d& x, double t) const;

 private:
  Envelope envelope(const WaveComponent& c, const Eigen::Vector3d& x, double t) const;

  Water water_;
  std::vector<WaveComponent> components_;
  std::optional<WaveFront> front_;
  CurrentProfile current_ = CurrentProfile::none();
  SurfaceKinematics surface_ = SurfaceKinematics::Wheeler;
};

}  // namespace flexmoor::hydro
