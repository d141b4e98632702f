#pragma once
// The irregular forms of `waves:` (read_sea.cpp): a sea from a spectrum, a measured elevation
// record, and the ramp-up in time of any sea. Parsing and validation only; build_ocean.cpp makes
// the components.
#include <optional>
#include <string>
#include <vector>

#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

// The keys of `waves:` with `spectrum:` (beside kinematics_above_mean, front and ramp_up).
const std::vector<std::string>& spectralSeaKeys();

// waves: {spectrum, [components: 200], [discretisation: random_bins], [repeat_period], [seed: 1],
// [heading: 0], [spreading: {s, directions}], [band: [0.5, 4]]}, into h.spectral.
void readSpectralSea(CaseBuilder& b, Fields& waves, OceanSpec& h);

// measured: {table: [[t, eta], ...] | file: CSV, [heading: 0], [at: [x, y]], [cutoff: f]}, into
// h.measured.
void readMeasuredSea(CaseBuilder& b, const YAML::Node& n, const std::string& path, OceanSpec& h);

// ramp_up: {duration, [start: 0]}.
std::optional<hydro::TimeRamp> readRamp(CaseBuilder& b, const YAML::Node& n,
                                        const std::string& path);

}  // namespace flexmoor::app
