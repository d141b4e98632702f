#pragma once
// A section as a case file's `sections:` states it: a cable section (its area, density, material
// and axial damping) or a membrane section (its thickness, density and membrane material), the
// integration order of its elements, and the Morison coefficients of the lines made of it.
#include <optional>

#include "apps/problem/ocean_spec.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"

namespace flexmoor::app {

struct SectionSpec {
  element::CableSection section;
  int quadrature = 0;  // Gauss points per element; 0 = as many as the element has nodes
  // A membrane section (`thickness:` instead of `area:`); quadrature 0 = the element's default.
  bool is_membrane = false;
  element::MembraneSection membrane;
  std::optional<LineHydroSpec> hydro;  // `hydro:`: Morison loads on the lines of this section
};

}  // namespace flexmoor::app
