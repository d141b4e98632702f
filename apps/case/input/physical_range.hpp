#pragma once
// Ranges that no physical input leaves, for the values whose size physics fixes more closely than
// Input::quantity's bound on every value: the case's gravity, the water's density and a section's
// density. A value outside is an input error stated with its range and the reason for it.
#include <string>

#include "apps/case/input/yaml_input.hpp"

namespace flexmoor::app {

struct PhysicalRange {
  Dimension dimension;
  double low = 0.0, high = 0.0;  // on the magnitude, in SI; low 0: no lower bound
  const char* si_unit;           // "m/s^2"
  const char* us_unit;           // "ft/s^2"
  const char* reason;            // why no physical input lies beyond
};

// Gravity: at most 100 m/s^2, ten times the Earth's (9.78 to 9.83 m/s^2).
extern const PhysicalRange kGravityRange;
// The sea's density: 500 to 2000 kg/m^3 (fresh water 1000, sea water 1025, the densest brines
// 1250).
extern const PhysicalRange kWaterDensityRange;
// A section's density (its mass per length over its area): at most 1e6 kg/m^3, over forty times
// the densest metal's (osmium, 22,590 kg/m^3): room for an equivalent density over a small area.
extern const PhysicalRange kSectionDensityRange;

// Whether |value| (in the case's units) lies in `range`; when not, reports at `n`
// "PATH: out of range (got 1e+308 ft/s^2, expected at most 328.084 ft/s^2 (100 m/s^2): REASON)".
// `got` describes the value when it is not the node's own text ("a magnitude of ...").
bool inPhysicalRange(Input& in, const YAML::Node& n, const std::string& path, double value,
                     const PhysicalRange& range, const std::string& got = "");

}  // namespace flexmoor::app
