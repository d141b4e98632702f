#include "libhydro/seabed/seabed_line_load.hpp"

#include <utility>

#include "libhydro/seabed/seabed_point_force.hpp"

namespace flexmoor::hydro {

SeabedLineLoad::SeabedLineLoad(Bathymetry bed, SeabedProperties properties,
                               std::vector<double> widths, std::vector<double> node_lengths)
    : bed_(std::move(bed)),
      properties_(properties),
      widths_(std::move(widths)),
      node_lengths_(std::move(node_lengths)) {}

model::PointForce SeabedLineLoad::evaluate(const model::LoadPoint& p, bool jacobians) const {
  if (p.element < 0 || p.element >= static_cast<int>(widths_.size())) return {};
  const double width = widths_[p.element];
  if (!(width > 0.0)) return {};
  const double node_length =
      p.element < static_cast<int>(node_lengths_.size()) ? node_lengths_[p.element] : 1.0;
  return seabedPointForce(
      seabedLoadAt(bed_, properties_, p.position, width, p.velocity, node_length), jacobians);
}

}  // namespace flexmoor::hydro
