// The liquids that fill membranes on the built model: their walls measured, and each that
// encloses its liquid put on the model (libhydro/loads/enclosed_fluid.hpp).
#include "apps/case/build/build_enclosed_fluid.hpp"

#include <cmath>

#include "apps/common/format_number.hpp"

namespace flexmoor::app {

std::string enclosureProblem(const Case& c, const std::vector<int>& elements,
                             const std::string& where) {
  const std::string on = where + ".on: ";
  const std::string length = unitNames(c.units).length;
  if (elements.empty())
    return on +
           "names no membranes (got surfaces without membrane elements, expected the "
           "membranes that hold the liquid)";
  for (const int e : elements)
    if (e < 0 || e >= c.model->elementCount())
      return on + "element " + std::to_string(e) + " is not in the mesh (" +
             std::to_string(c.model->elementCount()) + " elements, 0-based)";
  const hydro::Enclosure enclosure =
      hydro::measureEnclosure(*c.model, elements, c.model->initialState());
  if (enclosure.mixed)
    return on +
           "mixes axisymmetric meridians and 3-D membranes (expected one kind for one "
           "liquid)";
  // A closed wall, or one open only in vertical planes, has int n_z dA = 0; the quadrature
  // integrates it to round-off (measured below 1e-13 of the area).
  if (std::abs(enclosure.vertical_area) > 1e-6 * enclosure.area)
    return on + "does not enclose the liquid (got a vertical projected area of " +
           formatNumber(std::abs(enclosure.vertical_area)) + " " + length +
           "^2 open to it, expected a closed surface or openings in vertical planes only, as a "
           "tube between symmetry planes)";
  if (std::abs(enclosure.volume) <= 1e-9 * std::pow(enclosure.area, 1.5))
    return on + "encloses no volume in its reference shape (got " + formatNumber(enclosure.volume) +
           " " + length + "^3, expected the liquid's volume: the mass is lumped from it)";
  return "";
}

std::vector<SpecError> buildEnclosedFluids(const std::vector<EnclosedFluidSpec>& fluids, Case& c) {
  std::vector<SpecError> errors;
  for (const EnclosedFluidSpec& s : fluids) {
    if (const std::string problem = enclosureProblem(c, s.elements, s.where); !problem.empty())
      errors.push_back({s.line, problem});
    else
      hydro::addEnclosedFluid(*c.model, s.elements, s.fluid);
  }
  return errors;
}

}  // namespace flexmoor::app
