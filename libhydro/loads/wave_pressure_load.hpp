#pragma once
// The incident wave pressure on a membrane (docs/theory.md#wave-pressure-on-membranes): the gauge
// pressure of the sea (hydrostatic -rho g z plus the dynamic linear-wave pressure, no diffraction
// or radiation) at the deformed position of each integration point, zero above the surface, as a
// follower load along the current normal n = y,1 x y,2 (load_point.hpp's SurfaceLoad).
//
// Which side the water is on: the follower-pressure convention pushes the surface along +n for a
// positive pressure, which is water on the side n points away from (WaterSide::Negative). Water
// on the side n points to (WaterSide::Positive: outside a closed body whose normals point out)
// pushes along -n, so the load returns -p there.
//
// The gradient dp/dy is Sea's closed form (FluidGradient); at the free surface p is continuous
// and its gradient is not: a wet point takes the water's, a dry one zero.
#include <memory>

#include "libhydro/waves/sea.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

enum class WaterSide { Positive, Negative };  // the side n = y,1 x y,2 points to, or the other

class IncidentPressureLoad final : public model::SurfaceLoad {
 public:
  IncidentPressureLoad(std::shared_ptr<const Sea> sea, WaterSide side);

  model::PointPressure evaluate(const model::LoadPoint& p, bool jacobians) const override;
  WaterSide side() const { return side_; }

 private:
  std::shared_ptr<const Sea> sea_;
  std::shared_ptr<const Sea>
      still_;  // sea_ without its waves, for static solves (LoadPoint::still)
  WaterSide side_;
};

}  // namespace flexmoor::hydro
