#pragma once
// A 10 m steel wire (A = 1 cm^2, hydro diameter 11.3 mm, Cn 1.2, Ct 0.02, Ca 1.0) of 4 L3
// elements, 20 m down in 100 m of water, both ends fixed, the far end pulled along x by
// `end_pull` (a YAML length), moving in the x-z plane: the case's text from `materials:` to
// `water:`; the caller adds the units, the sea and the steps.
#include <string>

namespace flexmoor::test {

inline std::string submergedWire(const std::string& end_pull) {
  return R"(materials:
  steel: {type: linear_elastic, E: 2.0e11 Pa}
sections:
  wire: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3,
         hydro: {diameter: 0.0113 m, Cn: 1.2, Ct: 0.02, Ca: 1.0}}
lines:
  - {name: cable, from: [0, 0, -20 m], to: [10 m, 0, -20 m], elements: 4, order: 2, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z], displacement: [)" +
         end_pull + R"(, 0, 0]}
  - {nodes: cable, fix: [y]}
water: {density: 1025 kg/m^3, depth: 100 m}
)";
}

}  // namespace flexmoor::test
