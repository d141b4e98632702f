#include "libhydro/seabed/seabed_line_load.hpp"

#include <utility>

namespace flexmoor::hydro {

SeabedLineLoad::SeabedLineLoad(Bathymetry bed, SeabedProperties properties,
                               std::vector<double> widths)
    : bed_(std::move(bed)), properties_(properties), widths_(std::move(widths)) {}

model::PointForce SeabedLineLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  model::PointForce out;
  if (p.element < 0 || p.element >= static_cast<int>(widths_.size())) return out;
  const double width = widths_[p.element];
  if (!(width > 0.0)) return out;
  const SeabedPointLoad s = seabedLoadAt(bed_, properties_, p.position, width, p.velocity);
  out.force = s.force;
  if (!jacobians) return out;
  out.d_position = s.d_position;
  out.d_velocity = s.d_velocity;
  return out;
}

}  // namespace flexmoor::hydro
