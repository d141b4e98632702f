#pragma once
// Two 10 kg masses hanging on 1000 N/m springs under g = 10 m/s^2 (omega = 10 rad/s, static
// deflection m g / k = 0.1 m): nodes 1 and 3 fixed, mass 2 held in x, y and z by a support
// (for a step's release: to let go), mass 4 free in z, which gives a static step something to
// solve. The case's text up to its steps, the first of them a static step; the caller appends
// its dynamic step (and anything after).
#include <string>

namespace flexmoor::test {

inline std::string hangingMassesCase() {
  return R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [0, 0, -1 m]
  3: [1 m, 0, 0]
  4: [1 m, 0, -1 m]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 1000 N/m}
  - {type: point_mass, node: 2, mass: 10 kg}
  - {type: spring, nodes: [3, 4], stiffness: 1000 N/m}
  - {type: point_mass, node: 4, mass: 10 kg}
supports:
  - {nodes: [1, 3], fix: [x, y, z]}
  - {node: 2, fix: [x, y, z]}
  - {node: 4, fix: [x, y]}
loads:
  gravity: {g: 10 m/s^2}
steps:
  - static: {}
)";
}

}  // namespace flexmoor::test
