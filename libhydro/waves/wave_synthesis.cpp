#include "libhydro/waves/wave_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {
namespace {

const double kPi = std::acos(-1.0);

// A uniform number in [0, 1) from the top 53 bits of one 64-bit draw.
double unit(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

// A uniform number in (0, 1): the same bits, centred in their interval (never 0, so that a
// random frequency in a band from 0 is never 0).
double openUnit(std::mt19937_64& engine) {
  return (static_cast<double>(engine() >> 11) + 0.5) * 0x1.0p-53;
}

// A frequency of the sea before phases and directions.
struct Frequency {
  double omega, amplitude;
};

std::vector<Frequency> equalGrid(const WaveSpectrum& s, const SynthesisOptions& o, double lo,
                                 double hi, double& d_omega) {
  std::vector<Frequency> out;
  if (o.repeat_period > 0.0) {
    d_omega = 2.0 * kPi / o.repeat_period;
    const long first = std::max(1L, static_cast<long>(std::ceil(lo / d_omega)));
    const long last = static_cast<long>(std::floor(hi / d_omega));
    for (long m = first; m <= last; ++m) out.push_back({m * d_omega, 0.0});
  } else {
    d_omega = (hi - lo) / o.components;
    // The grid frequency nearest each bin's centre (never 0).
    for (int i = 0; i < o.components; ++i)
      out.push_back({std::round(lo / d_omega + i + 0.5) * d_omega, 0.0});
  }
  if (out.empty())
    throw std::invalid_argument("wave synthesis: the repeat period puts no frequency in the band");
  for (Frequency& f : out) f.amplitude = std::sqrt(2.0 * s.density(f.omega) * d_omega);
  return out;
}

std::vector<Frequency> equalEnergyBins(const WaveSpectrum& s, double lo, double hi, int n) {
  const std::vector<double> edges = equalEnergyEdges(s, lo, hi, n);
  const double amplitude = std::sqrt(2.0 * s.moment(0, lo, hi) / n);
  std::vector<Frequency> out;
  for (int i = 0; i < n; ++i) {
    const double m0 = s.moment(0, edges[i], edges[i + 1]);
    const double centroid =
        m0 > 0.0 ? s.moment(1, edges[i], edges[i + 1]) / m0 : 0.5 * (edges[i] + edges[i + 1]);
    out.push_back({centroid, amplitude});
  }
  return out;
}

}  // namespace

std::vector<double> equalEnergyEdges(const WaveSpectrum& s, double lo, double hi, int n) {
  const double share = s.moment(0, lo, hi) / n;
  std::vector<double> edges{lo};
  for (int i = 1; i < n; ++i) {
    // The edge after edges[i - 1] with `share` between them: int_prev^w S increases with w.
    // Bracketed from the mean bin width, doubled until it holds the share, then bisected.
    const double prev = edges.back();
    double a = prev, b = std::min(hi, prev + (hi - lo) / n);
    while (b < hi && s.moment(0, prev, b) < share) {
      a = b;
      b = std::min(hi, prev + 2.0 * (b - prev));
    }
    while (b - a > 1e-13 * hi) {
      const double mid = 0.5 * (a + b);
      (s.moment(0, prev, mid) < share ? a : b) = mid;
    }
    edges.push_back(0.5 * (a + b));
  }
  edges.push_back(hi);
  return edges;
}

SynthesisedSea synthesise(const WaveSpectrum& s, const SynthesisOptions& o, double depth,
                          double g) {
  const bool counted = !(o.discretisation == Discretisation::Equal && o.repeat_period > 0.0);
  if ((counted && o.components < 1) || !(o.omega_max_ratio > o.omega_min_ratio) ||
      !(o.omega_min_ratio >= 0.0) || o.directions < 1)
    throw std::invalid_argument(
        "wave synthesis: needs components >= 1, 0 <= min < max and directions >= 1");
  const double wp = s.peakFrequency();
  const double lo = o.omega_min_ratio * wp, hi = o.omega_max_ratio * wp;
  const std::vector<Direction> directions =
      o.spreading_s ? discretise(CosineSpreading(*o.spreading_s, o.heading), o.directions)
                    : std::vector<Direction>{{o.heading, 1.0}};
  SynthesisedSea sea;
  std::vector<Frequency> frequencies;
  std::mt19937_64 engine(o.seed);
  double d_omega = (hi - lo) / o.components;
  switch (o.discretisation) {
    case Discretisation::Equal:
      frequencies = equalGrid(s, o, lo, hi, d_omega);
      sea.repeat_period = 2.0 * kPi / d_omega;
      break;
    case Discretisation::EqualEnergy:
      frequencies = equalEnergyBins(s, lo, hi, o.components);
      break;
    case Discretisation::RandomBins:
      break;  // drawn below, bin by bin, between the phases
  }
  const int n = o.discretisation == Discretisation::RandomBins
                    ? o.components
                    : static_cast<int>(frequencies.size());
  sea.frequencies = n;
  sea.components.reserve(static_cast<size_t>(n) * directions.size());
  for (int i = 0; i < n; ++i) {
    Frequency f{};
    if (o.discretisation == Discretisation::RandomBins) {
      f.omega = lo + (i + openUnit(engine)) * d_omega;
      f.amplitude = std::sqrt(2.0 * s.density(f.omega) * d_omega);
    } else {
      f = frequencies[i];
    }
    const double k = waveNumber(f.omega, depth, g);
    for (const Direction& d : directions) {
      WaveComponent c;
      c.omega = f.omega;
      c.k = k;
      c.amplitude = f.amplitude * std::sqrt(d.weight);
      c.heading = d.heading;
      c.phase = 2.0 * kPi * unit(engine);
      sea.components.push_back(c);
    }
  }
  return sea;
}

}  // namespace flexmoor::hydro
