#pragma once
// The sea a structure sits in: still water, a list of linear wave components (a regular wave is
// one; an irregular sea adds more), an optional wave-train front, an optional ramp-up in time
// (time_ramp.hpp; it multiplies the front's envelope), a current, and the treatment of
// the kinematics above the mean level. It answers what the loads need at a point and time: the
// surface elevation above it, whether the point is wet, the fluid velocity and local
// acceleration, and the gauge pressure (hydrostatic plus dynamic), and on request their
// gradients in position.
//
// What of each component does not change with the point and the time (k cos beta, k sin beta,
// the depth factors, the front's speed and ramp) is computed once as components are added, so a
// point costs one sincos and one exp per component, with its gradient or without, taken over
// all components at once (component_sums.hpp); a long-crested sea without a front (one heading,
// one envelope for all components) by the shorter sums of long_crested_sums.hpp.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "libhydro/water/current_profile.hpp"
#include "libhydro/water/water.hpp"
#include "libhydro/waves/component_sums.hpp"
#include "libhydro/waves/time_ramp.hpp"
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

// The derivatives of a wet FluidPoint's fields in the point's position (zero where dry). Closed
// form: linear theory and the front's ramp differentiated, through Wheeler's z'(x, y, z) (the
// chain rule with grad eta) or constant extrapolation (d/dz = 0 above the mean level, one-sided
// at z = 0), and the current's shear (CurrentProfile::shear: one-sided at a table's samples,
// zero at the bed for a power law, whose shear is singular there). No central differences.
struct FluidGradient {
  Eigen::Matrix3d velocity = Eigen::Matrix3d::Zero();      // d v / d y
  Eigen::Matrix3d acceleration = Eigen::Matrix3d::Zero();  // d a / d y
  Eigen::Vector3d pressure = Eigen::Vector3d::Zero();      // d p / d y
  Eigen::Vector3d elevation = Eigen::Vector3d::Zero();     // (d eta / dx, d eta / dy, 0), always
};

class Sea {
 public:
  explicit Sea(Water water) : water_(water) {}

  void addComponent(const WaveComponent& c);
  void setFront(const WaveFront& front);
  void setRamp(const TimeRamp& ramp) { ramp_ = ramp; }
  void setCurrent(const CurrentProfile& current) { current_ = current; }
  void setSurfaceKinematics(SurfaceKinematics k) { surface_ = k; }

  const Water& water() const { return water_; }
  // The same water and current without waves: what a static solve's loads see (still water,
  // as MoorDyn, MAP++ and OrcaFlex take their statics).
  Sea stillWater() const {
    Sea still(water_);
    still.current_ = current_;
    still.surface_ = surface_;
    return still;
  }
  const std::vector<WaveComponent>& components() const { return components_; }

  double elevation(const Eigen::Vector3d& x, double t) const;
  FluidPoint at(const Eigen::Vector3d& x, double t) const { return evaluate(x, t, nullptr); }
  FluidPoint at(const Eigen::Vector3d& x, double t, FluidGradient& gradient) const {
    return evaluate(x, t, &gradient);
  }

 private:
  // The phases and envelopes of every component into `s`, and the elevation with its gradient.
  double phases(const Eigen::Vector3d& x, double t, ComponentScratch& s,
                Eigen::Vector3d* elevation_gradient) const;
  FluidPoint evaluate(const Eigen::Vector3d& x, double t, FluidGradient* gradient) const;
  Envelope rampAt(double t) const;  // the ramp's envelope, or 1
  // Every component along one heading and no front: long_crested_sums.hpp's sums.
  bool oneEnvelope() const { return long_crested_ && !front_; }

  Water water_;
  std::vector<WaveComponent> components_;
  ComponentTable table_;      // the components' terms
  bool long_crested_ = true;  // every component along the first's heading
  std::optional<WaveFront> front_;
  std::vector<ComponentFront> fronts_;  // one per component when there is a front
  std::optional<TimeRamp> ramp_;
  CurrentProfile current_ = CurrentProfile::none();
  SurfaceKinematics surface_ = SurfaceKinematics::Wheeler;
};

}  // namespace flexmoor::hydro
