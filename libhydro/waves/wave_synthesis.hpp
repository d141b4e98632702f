#pragma once
// A sea-state spectrum (wave_spectrum.hpp), optionally spread over directions
// (directional_spreading.hpp), made into linear wave components with seeded random phases, so that
// an irregular sea is a Sea with many components. The frequency band [r_min wp, r_max wp] is cut
// into `components` bins by one of three rules:
//   Equal: equal bins d omega, each component on the FFT grid omega = m d omega (m an integer),
//     a = sqrt(2 S(omega) d omega): the sea repeats exactly every T = 2 pi / d omega (given, or
//     2 pi components / band width), and its elevation at a point is an inverse FFT
//     (elevation_record.hpp).
//   RandomBins: equal bins, each component at a frequency drawn uniformly inside its bin, a =
//     sqrt(2 S(omega) d omega): no repeat period.
//   EqualEnergy: bins of equal m0, each component at its bin's centroid m1 / m0 with a = sqrt(2
//     m0_band / N): narrow bins near the peak, wide ones in the tails; no repeat period.
// Random numbers: a 64-bit Mersenne Twister (std::mt19937_64, whose sequence the C++ standard
// fixes) from the seed, taken bit by bit: a uniform number is the top 53 bits of one draw times
// 2^-53, never through a standard-library distribution (whose algorithm each library chooses), so
// that a seed gives the same sea to the last bit with every compiler and library. Per frequency,
// in order: its offset in the bin (RandomBins only), then one phase per direction.
#include <cstdint>
#include <optional>
#include <vector>

#include "libhydro/waves/directional_spreading.hpp"
#include "libhydro/waves/wave_component.hpp"
#include "libhydro/waves/wave_spectrum.hpp"

namespace flexmoor::hydro {

enum class Discretisation { Equal, RandomBins, EqualEnergy };

struct SynthesisOptions {
  int components = 200;          // frequencies (each in every direction)
  double omega_min_ratio = 0.5;  // band [ratio_min wp, ratio_max wp], 0 <= min < max
  double omega_max_ratio = 4.0;
  uint64_t seed = 1;
  Discretisation discretisation = Discretisation::RandomBins;
  // Equal only: the repeat period T of the FFT grid (d omega = 2 pi / T; the components are the
  // grid's frequencies in the band, `components` is not used); 0 to take d omega from components.
  double repeat_period = 0.0;
  double heading = 0.0;               // mean direction of travel, rad
  std::optional<double> spreading_s;  // cos-2s exponent s; none: long-crested
  int directions = 1;                 // directions of the spreading
};

struct SynthesisedSea {
  std::vector<WaveComponent> components;  // frequency by frequency, directions within each
  int frequencies = 0;
  double repeat_period = 0.0;  // Equal: T = 2 pi / d omega; 0: the sea does not repeat
};

SynthesisedSea synthesise(const WaveSpectrum& s, const SynthesisOptions& o, double depth, double g);

// The frequencies bounding the EqualEnergy bins of the band [lo, hi] (n + 1 of them, lo and hi
// at the ends), each bin holding m0(lo, hi) / n: bisection to 1e-13 relative on the spectrum's
// band moment.
std::vector<double> equalEnergyEdges(const WaveSpectrum& s, double lo, double hi, int n);

}  // namespace flexmoor::hydro
