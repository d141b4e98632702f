#pragma once
// Seabed contact of line elements (seabed_contact.hpp, MoorDyn v2's convention) through
// libstruct's load-point interface: per unstretched length, at every integration point below the
// bed, the penalty spring-damper along the bed's normal over the projected width d and smooth
// friction along the bed.
#include <vector>

#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

class SeabedLineLoad final : public model::LineLoad {
 public:
  // widths[e]: the contact width (hydrodynamic diameter) of model element e; 0 (or e past the
  // end) for an element that does not touch the bed.
  SeabedLineLoad(Bathymetry bed, SeabedProperties properties, std::vector<double> widths);

  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override;
  model::LengthMeasure measure() const override { return model::LengthMeasure::Reference; }

 private:
  Bathymetry bed_;
  SeabedProperties properties_;
  std::vector<double> widths_;
};

}  // namespace flexmoor::hydro
