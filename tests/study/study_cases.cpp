#include "tests/study/study_cases.hpp"

#include <fstream>

namespace flexmoor::test {

std::filesystem::path writeText(const std::filesystem::path& dir, const std::string& name,
                                const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

void writeOscillatorCase(const std::filesystem::path& dir) {
  writeText(dir, "osc.yaml", R"(units: SI
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
  - dynamic: {dt: 0.00314159265359 s, steps: 400, release: [{node: 2, dofs: [z]}],
              tolerance: 1e-8}
)");
}

std::string oscillatorStudy(const std::string& variations) {
  return "title: oscillator study\ncase: osc.yaml\n" + variations + R"(
collect:
  - name: drop
    quantity: displacement_z
    node: 2
    spectrum: {segment: 0.628318530718 s}
)";
}

}  // namespace flexmoor::test
