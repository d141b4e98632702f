#include "apps/case/input/physical_range.hpp"

#include <cmath>

#include "apps/case/input/units.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {

const PhysicalRange kGravityRange{
    kind::kAcceleration.dimension,
    0.0,
    100.0,
    "m/s^2",
    "ft/s^2",
    "ten times the Earth's, 9.78 to 9.83 m/s^2; no sea lies under more"};
const PhysicalRange kWaterDensityRange{
    kind::kDensity.dimension,
    500.0,
    2000.0,
    "kg/m^3",
    "slug/ft^3",
    "the density of a sea: fresh water 1000 kg/m^3, sea water 1025, the densest brines 1250"};
const PhysicalRange kSectionDensityRange{
    kind::kDensity.dimension,
    0.0,
    1e6,
    "kg/m^3",
    "slug/ft^3",
    "over forty times the densest metal's (osmium, 22,590 kg/m^3): room for a section's "
    "equivalent density over a small area, not more"};

bool inPhysicalRange(Input& in, const YAML::Node& n, const std::string& path, double value,
                     const PhysicalRange& range, const std::string& got) {
  const double scale = systemScale(range.dimension, in.units);  // SI of one case unit
  const double magnitude = std::abs(value) * scale;
  if (magnitude >= range.low && magnitude <= range.high) return true;
  const bool us = in.units == UnitSystem::US;
  const std::string unit = us ? range.us_unit : range.si_unit;
  // The range in the case's units, with the SI one beside it in a US case.
  const auto span = [&](double factor, const std::string& u) {
    return (range.low > 0.0 ? formatNumber(range.low * factor) + " to " : "at most ") +
           formatNumber(range.high * factor) + " " + u;
  };
  const std::string expected =
      span(1.0 / scale, unit) + (us ? " (" + span(1.0, range.si_unit) + ")" : "");
  in.diag.error(n, path + ": out of range (got " +
                       (got.empty() ? formatNumber(value) + " " + unit : got) + ", expected " +
                       expected + ": " + range.reason + ")");
  return false;
}

}  // namespace flexmoor::app
