#include "tests/study/study_cases.hpp"

#include <fstream>

#include "tests/support/hanging_masses.hpp"

namespace flexmoor::test {

std::filesystem::path writeText(const std::filesystem::path& dir, const std::string& name,
                                const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

void writeOscillatorCase(const std::filesystem::path& dir) {
  writeText(
      dir, "osc.yaml",
      hangingMassesCase() +
          R"(  - dynamic: {dt: 0.00314159265359 s, steps: 400, release: [{node: 2, dofs: [z]}],
              tolerance: 1e-8, max_iterations: 30}
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
