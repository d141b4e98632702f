#pragma once
// Seabed contact of line elements (seabed_contact.hpp, MoorDyn v2's convention) through
// libstruct's load-point interface: per unstretched length, at every integration point below the
// bed, the penalty spring-damper along the bed's normal over the projected width d and friction
// along the bed (seabed_friction.hpp).
#include <vector>

#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

class SeabedLineLoad final : public model::LineLoad {
 public:
  // widths[e]: the contact width (hydrodynamic diameter) of model element e; 0 (or e past the
  // end) for an element that does not touch the bed. node_lengths[e]: its unstretched node
  // spacing, over which the moordyn friction law spreads the friction damping of a node
  // (MoorDyn's segment length; seabed_friction.hpp); 1 when not given.
  SeabedLineLoad(Bathymetry bed, SeabedProperties properties, std::vector<double> widths,
                 std::vector<double> node_lengths = {});

  model::PointForce evaluate(const model::LoadPoint& p, bool jacobians) const override;
  model::LengthMeasure measure() const override { return model::LengthMeasure::Reference; }
  bool contact() const override { return true; }

 private:
  Bathymetry bed_;
  SeabedProperties properties_;
  std::vector<double> widths_;
  std::vector<double> node_lengths_;
};

}  // namespace flexmoor::hydro
