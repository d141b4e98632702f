#include "libhydro/loads/wave_pressure_load.hpp"

namespace flexmoor::hydro {

IncidentPressureLoad::IncidentPressureLoad(std::shared_ptr<const Sea> sea, WaterSide side)
    : sea_(std::move(sea)), still_(std::make_shared<const Sea>(sea_->stillWater())), side_(side) {}

model::PointPressure IncidentPressureLoad::evaluate(const model::LoadPoint& p,
                                                    bool jacobians) const {
  const double sign = side_ == WaterSide::Negative ? 1.0 : -1.0;
  model::PointPressure out;
  FluidGradient g;
  const Sea& sea = p.still ? *still_ : *sea_;
  const FluidPoint f = jacobians ? sea.at(p.position, p.time, g) : sea.at(p.position, p.time);
  if (!f.wet) return out;  // zero above the surface, and its gradient
  out.pressure = sign * f.pressure;
  if (jacobians) out.d_position = sign * g.pressure;
  return out;
}

}  // namespace flexmoor::hydro
