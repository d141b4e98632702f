#include "libhydro/loads/wave_pressure_load.hpp"

#include "libhydro/waves/flow_gradient.hpp"

namespace flexmoor::hydro {

IncidentPressureLoad::IncidentPressureLoad(std::shared_ptr<const Sea> sea, WaterSide side)
    : sea_(std::move(sea)), side_(side) {}

double IncidentPressureLoad::pressure(const Eigen::Vector3d& x, double t) const {
  const FluidPoint f = sea_->at(x, t);
  return f.wet ? f.pressure : 0.0;
}

model::PointPressure IncidentPressureLoad::evaluate(const model::LoadPoint& p,
                                                    bool jacobians) const {
  const double sign = side_ == WaterSide::Negative ? 1.0 : -1.0;
  model::PointPressure out;
  out.pressure = sign * pressure(p.position, p.time);
  if (!jacobians) return out;
  const double h = flowGradientStep(*sea_);
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d plus = p.position, minus = p.position;
    plus(k) += h;
    minus(k) -= h;
    out.d_position(k) = sign * (pressure(plus, p.time) - pressure(minus, p.time)) / (2.0 * h);
  }
  return out;
}

}  // namespace flexmoor::hydro
