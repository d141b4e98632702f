// The liquids of `loads: enclosed_fluid:` (read_enclosed_fluid.cpp) on the built model: their
// walls measured, and each that encloses its liquid put on the model
// (libhydro/loads/enclosed_fluid.hpp).
#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/common/format_number.hpp"
#include "libhydro/loads/enclosed_fluid.hpp"

namespace flexmoor::app {
namespace {

// Whether the membranes enclose a volume the liquid can fill.
bool checkEnclosure(CaseBuilder& b, const EnclosedFluidSpec& s, const hydro::Enclosure& e) {
  const std::string on = s.where + ".on";
  const std::string length = unitNames(b.c.units).length;
  if (s.elements.empty()) {
    b.diag.error(s.line, on + ": names no membranes (got surfaces without membrane elements, "
                              "expected the membranes that hold the liquid)");
    return false;
  }
  if (e.mixed) {
    b.diag.error(s.line, on + ": mixes axisymmetric meridians and 3-D membranes (expected one "
                              "kind for one liquid)");
    return false;
  }
  // A closed wall, or one open only in vertical planes, has int n_z dA = 0; the quadrature
  // integrates it to round-off (measured below 1e-13 of the area).
  if (std::abs(e.vertical_area) > 1e-6 * e.area) {
    b.diag.error(s.line, on + ": does not enclose the liquid (got a vertical projected area of " +
                             formatNumber(std::abs(e.vertical_area)) + " " + length +
                             "^2 open to it, expected a closed surface or openings in vertical "
                             "planes only, as a tube between symmetry planes)");
    return false;
  }
  if (std::abs(e.volume) <= 1e-9 * std::pow(e.area, 1.5)) {
    b.diag.error(s.line, on + ": encloses no volume in its reference shape (got " +
                             formatNumber(e.volume) + " " + length +
                             "^3, expected the liquid's volume: the mass is lumped from it)");
    return false;
  }
  return true;
}

}  // namespace

void buildEnclosedFluids(CaseBuilder& b) {
  for (const EnclosedFluidSpec& s : b.enclosed_fluids) {
    const hydro::Enclosure e = hydro::measureEnclosure(b.model, s.elements, b.model.initialState());
    if (checkEnclosure(b, s, e) && s.fluid) hydro::addEnclosedFluid(b.model, s.elements, *s.fluid);
  }
}

}  // namespace flexmoor::app
