#include "libhydro/loads/morison_line_load.hpp"

#include <cmath>
#include <utility>

namespace flexmoor::hydro {

MorisonLineLoad::MorisonLineLoad(std::shared_ptr<const Sea> sea,
                                 std::vector<std::optional<MorisonCoefficients>> sections,
                                 model::LengthMeasure measure)
    : sea_(std::move(sea)),
      still_(std::make_shared<const Sea>(sea_->stillWater())),
      sections_(std::move(sections)),
      measure_(measure) {}

// Per deformed length (Eq. E.1) or, for LengthMeasure::Reference, the same force values per
// unstretched length as MoorDyn applies them: the element integrates over the length the
// measure names, so the force per point is the same either way.
model::PointForce MorisonLineLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  model::PointForce out;
  if (p.element < 0 || p.element >= static_cast<int>(sections_.size()) || !sections_[p.element])
    return out;
  FluidGradient g;
  const Sea& sea = p.still ? *still_ : *sea_;
  const FluidPoint fluid = held_ && !p.still ? held_->at(p.element, p.position, p.time, g)
                           : jacobians       ? sea.at(p.position, p.time, g)
                                             : sea.at(p.position, p.time);
  if (!fluid.wet) return out;  // above the local surface: nothing (a line may pierce it)
  const MorisonCoefficients& c = *sections_[p.element];
  const Water& water = sea_->water();
  const MorisonPointLoad m = morisonLoad(c, water.density, p.tangent, p.velocity, p.acceleration,
                                         fluid.velocity, fluid.acceleration);
  const double area = 0.25 * std::acos(-1.0) * c.diameter * c.diameter;
  out.force = m.force + water.density * water.gravity * area * Eigen::Vector3d::UnitZ();
  if (!jacobians) return out;
  out.d_velocity = m.d_velocity;
  out.d_acceleration = m.d_acceleration;
  out.d_tangent = m.d_tangent;
  // d f / d y through the flow; the buoyancy's step at the surface is left out.
  out.d_position = m.d_fluid_velocity * g.velocity + m.d_fluid_acceleration * g.acceleration;
  return out;
}

}  // namespace flexmoor::hydro
