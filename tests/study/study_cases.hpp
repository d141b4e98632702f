#pragma once
// The tiny member cases of the study tests, written into a scratch directory: a 10 kg mass on a
// 1000 N/m spring (omega = 10 rad/s) held at the spring's unstretched length by a static step,
// then released by a dynamic step of 400 steps of T / 200 (two periods): it swings between 0 and
// -2 m g / k, a response z(t) = -(m g / k) (1 - cos(omega t)). A twin oscillator never held gives
// the static step something to solve.
#include <filesystem>
#include <string>

namespace flexmoor::test {

// osc.yaml in `dir`.
void writeOscillatorCase(const std::filesystem::path& dir);

// DIR/NAME with `text`.
std::filesystem::path writeText(const std::filesystem::path& dir, const std::string& name,
                                const std::string& text);

// A study of osc.yaml: `variations` (grid: and/or list: lines), collecting the mass's
// displacement_z as `drop` over the whole step with a spectrum of one period's segment.
std::string oscillatorStudy(const std::string& variations);

}  // namespace flexmoor::test
