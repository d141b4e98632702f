#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace flexmoor::hydro {
class WaveSpectrum;
}  // namespace flexmoor::hydro

namespace flexmoor::app {

// How the sea's components were made (build_ocean.cpp), for the results' metadata (the netCDF
// global attributes sea_kind, sea_components, sea_discretisation, sea_seed, sea_repeat_period and
// a spectrum's sea_spectrum_*, netcdf_writer.hpp).
struct SeaOrigin {
  std::string kind;              // "regular", "spectrum" or "measured"
  std::string discretisation;    // a spectrum's: "equal", "random_bins" or "equal_energy"
  std::optional<uint64_t> seed;  // a spectrum's
  double repeat_period = 0.0;    // the equal grid's or the record's period; 0: no repeat
  int components = 0;
  std::shared_ptr<const hydro::WaveSpectrum> spectrum;  // the target of a spectrum's sea
  std::pair<double, double> band{0.0, 0.0};  // its synthesised band [omega_min, omega_max], rad/s
};

}  // namespace flexmoor::app
