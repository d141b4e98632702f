// Irregular seas from a spectrum (libhydro/waves/wave_synthesis.hpp): for each discretisation
// (equal spacing on an FFT grid, random frequencies in equal bins, equal-energy bins), a long
// record's Welch spectrum (FFTW; Hann window, half overlap) gives back the target's Hs within 5%
// and Tp within 3% (the required bounds; each case held to just above what it measures); a seed
// gives the same elevation to the last bit, another seed another sea; the equal grid repeats
// with its stated period and its FFT record is the sum of cosines; equal-energy bins each hold
// m0 / N; spreading keeps the energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "libhydro/signal/welch.hpp"
#include "libhydro/waves/elevation_record.hpp"
#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/wave_synthesis.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665, kDepth = 150.0;
const double kPi = std::acos(-1.0);

Sea seaOf(const std::vector<WaveComponent>& components) {
  Sea sea(Water{1025.0, kDepth, kG});
  for (const WaveComponent& c : components) sea.addComponent(c);
  return sea;
}

// eta at the origin, t = 0, dt, ..., by the sum of cosines.
std::vector<double> record(const Sea& sea, double dt, int n) {
  std::vector<double> eta(n);
  for (int i = 0; i < n; ++i) eta[i] = sea.elevation(Eigen::Vector3d::Zero(), i * dt);
  return eta;
}

struct HsTp {
  double hs, tp;
};

// Hs = 4 sqrt(m0) of the Welch estimate (4096-sample segments, Hann, half overlap) and Tp of the
// target's family (its gamma held) fitted to the estimate by least squares over [0.5, 4] wp:
// S(w; Tp') = (Tp' / Tp) S(w Tp' / Tp; Tp) (the same m0), Tp' by golden section in [0.8, 1.25]
// Tp. A fit, since the raw peak of a 3 h estimate is not a stable figure: the estimate's bins
// scatter by 1 / sqrt(9 segments) = 33% while Pierson-Moskowitz falls by 0.8% only 3% off its
// peak (a peak-pick, smoothed over 5 bins, missed by up to 7% here).
HsTp welchHsTp(const std::vector<double>& eta, double dt, const WaveSpectrum& target) {
  const signal::SpectralEstimate e = signal::welch(eta, dt, 4096);
  const double wp = target.peakFrequency(), tp = 2.0 * kPi / wp;
  const auto misfit = [&](double trial) {
    const double r = trial / tp;
    double sum = 0.0;
    for (size_t k = 0; k < e.omega.size(); ++k)
      if (e.omega[k] >= 0.5 * wp && e.omega[k] <= 4.0 * wp)
        sum += std::pow(e.density[k] - r * target.density(e.omega[k] * r), 2);
    return sum;
  };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = 0.8 * tp, b = 1.25 * tp;
  for (int it = 0; it < 60; ++it) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    if (misfit(c) < misfit(d))
      b = d;
    else
      a = c;
  }
  return {4.0 * std::sqrt(e.moment(0)), 0.5 * (a + b)};
}
struct Case {
  const char* name;
  Discretisation discretisation;
  double gamma;                       // 1: Pierson-Moskowitz
  double hs_tolerance, tp_tolerance;  // relative
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class SpectrumRecord : public ::testing::TestWithParam<Case> {};

// A 3 h sea state (Hs 6 m, Tp 10 s) at dt = 0.5 s: 21,600 samples, 9 Welch segments of 2,048 s.
// The equal grid's repeat period is the record's 3 h (3,781 components in [0.5, 4] wp), its
// record one inverse FFT; the others 300 components, their record summed. Required: Hs within 5%
// and Tp within 3% of the target; each case held to just above what it measures (the seed fixes
// the record): Hs -1.51 / -0.70 / +0.61% (JONSWAP equal / random bins / equal energy), -0.88 /
// -0.12 / -0.62% (Pierson-Moskowitz); Tp +0.02 / +0.10 / +0.52%, +0.05 / +0.05 / +0.26%. The band
// [0.5, 4] wp leaves out 0.32% of JONSWAP's m0 and 0.49% of Pierson-Moskowitz's (Hs -0.16%,
// -0.24%).
TEST_P(SpectrumRecord, WelchEstimateGivesBackHsAndTp) {
  const Case c = GetParam();
  const double hs = 6.0, tp = 10.0, dt = 0.5, duration = 10800.0;
  const int n = static_cast<int>(duration / dt);
  const WaveSpectrum s = WaveSpectrum::jonswap(hs, tp, c.gamma);
  SynthesisOptions o;
  o.seed = 12;
  o.discretisation = c.discretisation;
  o.components = 300;
  if (c.discretisation == Discretisation::Equal) o.repeat_period = duration;
  const SynthesisedSea sea = synthesise(s, o, kDepth, kG);
  std::vector<double> eta;
  if (c.discretisation == Discretisation::Equal) {
    EXPECT_DOUBLE_EQ(sea.repeat_period, duration);
    // d omega = 2 pi / 3 h: harmonics m = 540 .. 4320 of it in [0.5, 4] wp (an end may fall
    // either side of the band's edge by round-off).
    EXPECT_NEAR(sea.frequencies, 3781, 1);
    eta = elevationRecord(sea.components, sea.repeat_period, Eigen::Vector2d::Zero(), n);
  } else {
    EXPECT_EQ(sea.repeat_period, 0.0);
    eta = record(seaOf(sea.components), dt, n);
  }
  const HsTp e = welchHsTp(eta, dt, s);
  EXPECT_NEAR(e.hs / hs, 1.0, c.hs_tolerance) << c.name << ": Hs " << e.hs;
  EXPECT_NEAR(e.tp / tp, 1.0, c.tp_tolerance) << c.name << ": Tp " << e.tp;
  std::printf("%s: Welch Hs %.4f m (%+.2f%%), Tp %.3f s (%+.2f%%)\n", c.name, e.hs,
              100.0 * (e.hs / hs - 1.0), e.tp, 100.0 * (e.tp / tp - 1.0));
}

INSTANTIATE_TEST_SUITE_P(
    IrregularSea, SpectrumRecord,
    ::testing::Values(
        Case{"JonswapEqual", Discretisation::Equal, 3.3, 0.025, 0.0005},
        Case{"JonswapRandomBins", Discretisation::RandomBins, 3.3, 0.012, 0.002},
        Case{"JonswapEqualEnergy", Discretisation::EqualEnergy, 3.3, 0.01, 0.008},
        Case{"PiersonMoskowitzEqual", Discretisation::Equal, 1.0, 0.015, 0.001},
        Case{"PiersonMoskowitzRandomBins", Discretisation::RandomBins, 1.0, 0.0025, 0.001},
        Case{"PiersonMoskowitzEqualEnergy", Discretisation::EqualEnergy, 1.0, 0.01, 0.004}),
    [](const auto& info) { return std::string(info.param.name); });

// Every discretisation, long- and short-crested: two syntheses of one seed give Seas whose
// elevation and kinematics are equal to the last bit (compared as bytes) at 200 times and two
// points; a seed one apart gives a sea whose every phase and elevation differs.
TEST(IrregularSea, SeedGivesTheSameSeaToTheLastBit) {
  const WaveSpectrum s = WaveSpectrum::jonswap(4.0, 9.0, 3.3);
  for (const Discretisation d :
       {Discretisation::Equal, Discretisation::RandomBins, Discretisation::EqualEnergy}) {
    for (const bool spread : {false, true}) {
      SynthesisOptions o;
      o.seed = 7;
      o.components = 60;
      o.discretisation = d;
      if (spread) {
        o.spreading_s = 8.0;
        o.directions = 5;
        o.heading = 0.3;
      }
      const Sea a = seaOf(synthesise(s, o, kDepth, kG).components);
      const Sea b = seaOf(synthesise(s, o, kDepth, kG).components);
      o.seed = 8;
      const Sea c = seaOf(synthesise(s, o, kDepth, kG).components);
      ASSERT_EQ(a.components().size(), spread ? 300u : 60u);
      for (size_t i = 0; i < a.components().size(); ++i)
        EXPECT_NE(a.components()[i].phase, c.components()[i].phase) << i;
      int differing = 0;
      for (int i = 0; i < 200; ++i) {
        for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, -5), Eigen::Vector3d(30, -7, -20)}) {
          const double t = 3.7 * i;
          const FluidPoint pa = a.at(x, t), pb = b.at(x, t);
          EXPECT_EQ(std::memcmp(&pa.elevation, &pb.elevation, sizeof(double)), 0);
          EXPECT_EQ(std::memcmp(pa.velocity.data(), pb.velocity.data(), 3 * sizeof(double)), 0);
          EXPECT_EQ(std::memcmp(pa.acceleration.data(), pb.acceleration.data(), 3 * sizeof(double)),
                    0);
          EXPECT_EQ(std::memcmp(&pa.pressure, &pb.pressure, sizeof(double)), 0);
          differing += pa.elevation != c.elevation(x, t);
        }
      }
      EXPECT_EQ(differing, 400);
    }
  }
}

// The equal grid: every frequency a whole multiple of 2 pi / T (to 1e-12 relative), the elevation
// at t + T that at t (to 2e-13 of Hs, measured 6e-14: round-off in phases of up to omega T ~ 4,000
// rad), and the inverse-FFT record at 1,024 samples of T the sum of cosines (Sea::elevation) at
// every sample to 2e-13 of Hs (measured 3e-14), at the origin and 40 m off it, short-crested (5
// directions).
TEST(IrregularSea, EqualGridRepeatsAndItsFftRecordIsTheSumOfCosines) {
  const double hs = 3.0;
  const WaveSpectrum s = WaveSpectrum::jonswap(hs, 8.0, 2.0);
  SynthesisOptions o;
  o.discretisation = Discretisation::Equal;
  o.components = 120;
  o.spreading_s = 5.0;
  o.directions = 5;
  const SynthesisedSea synth = synthesise(s, o, kDepth, kG);
  const double T = synth.repeat_period, dw = 2.0 * kPi / T;
  // 120 bins over 3.5 wp: T = 2 pi 120 / (3.5 wp) = 120 Tp / 3.5.
  EXPECT_NEAR(T / (120.0 * 8.0 / 3.5), 1.0, 1e-14);
  for (const WaveComponent& c : synth.components)
    EXPECT_NEAR(c.omega / dw, std::round(c.omega / dw), 1e-12 * c.omega / dw);
  const Sea sea = seaOf(synth.components);
  const int samples = 1024;
  for (const Eigen::Vector2d& at : {Eigen::Vector2d(0, 0), Eigen::Vector2d(40, -10)}) {
    const Eigen::Vector3d x(at.x(), at.y(), 0.0);
    const std::vector<double> eta = elevationRecord(synth.components, T, at, samples);
    double worst = 0.0, worst_repeat = 0.0;
    for (int j = 0; j < samples; ++j) {
      const double t = j * T / samples;
      worst = std::max(worst, std::abs(eta[j] - sea.elevation(x, t)));
      worst_repeat = std::max(worst_repeat, std::abs(sea.elevation(x, t + T) - eta[j]));
    }
    EXPECT_LT(worst, 2e-13 * hs);
    EXPECT_LT(worst_repeat, 2e-13 * hs);
  }
}

// Equal-energy bins: each of the 50 bins between the edges holds m0_band / 50, the band's
// m0 and each bin's taken by an independent Simpson in 20,000 steps a bin (reference; its
// error ~1e-14), to 1e-10 relative (measured 2e-11: the edges are bisected to 1e-13, the band
// integral's own steps are wp / 4000); every component's a^2 / 2 is m0_band / 50 likewise.
TEST(IrregularSea, EqualEnergyBinsEachHoldM0OverN) {
  const WaveSpectrum s = WaveSpectrum::jonswap(5.0, 12.0, 3.3);
  const double wp = s.peakFrequency(), lo = 0.5 * wp, hi = 4.0 * wp;
  const int n = 50;
  const std::vector<double> edges = equalEnergyEdges(s, lo, hi, n);
  ASSERT_EQ(edges.size(), static_cast<size_t>(n + 1));
  const auto integral = [&](double a, double b) {
    const int steps = 20000;
    const double h = (b - a) / steps;
    double sum = s.density(a) + s.density(b);
    for (int i = 1; i < steps; ++i) sum += (i % 2 ? 4.0 : 2.0) * s.density(a + i * h);
    return sum * h / 3.0;
  };
  double band = 0.0;
  std::vector<double> bins;
  for (int i = 0; i < n; ++i) {
    bins.push_back(integral(edges[i], edges[i + 1]));
    band += bins.back();
  }
  for (int i = 0; i < n; ++i) EXPECT_NEAR(bins[i] / (band / n), 1.0, 1e-10) << "bin " << i;
  SynthesisOptions o;
  o.discretisation = Discretisation::EqualEnergy;
  o.components = n;
  const SynthesisedSea synth = synthesise(s, o, kDepth, kG);
  ASSERT_EQ(synth.components.size(), static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const WaveComponent& c = synth.components[i];
    EXPECT_NEAR(0.5 * c.amplitude * c.amplitude / (band / n), 1.0, 1e-10);
    EXPECT_GT(c.omega, edges[i]);
    EXPECT_LT(c.omega, edges[i + 1]);
  }
}

// Spreading shares each frequency's energy among its directions: sum a^2 / 2 over the 7
// directions of a frequency is that frequency's long-crested a^2 / 2 (to 1e-14, round-off of
// weights summing to 1), at the same frequencies (equal-energy bins: no random offsets).
TEST(IrregularSea, SpreadingKeepsEachFrequencysEnergy) {
  const WaveSpectrum s = WaveSpectrum::piersonMoskowitz(2.0, 7.0);
  SynthesisOptions o;
  o.components = 40;
  o.discretisation = Discretisation::EqualEnergy;
  const SynthesisedSea longc = synthesise(s, o, kDepth, kG);
  o.spreading_s = 15.0;
  o.directions = 7;
  const SynthesisedSea shortc = synthesise(s, o, kDepth, kG);
  ASSERT_EQ(shortc.components.size(), 280u);
  for (int i = 0; i < 40; ++i) {
    double energy = 0.0;
    for (int j = 0; j < 7; ++j) {
      const WaveComponent& c = shortc.components[7 * i + j];
      EXPECT_EQ(c.omega, longc.components[i].omega);
      energy += 0.5 * c.amplitude * c.amplitude;
    }
    const double a = longc.components[i].amplitude;
    EXPECT_NEAR(energy / (0.5 * a * a), 1.0, 1e-14);
  }
}

}  // namespace
}  // namespace flexmoor::hydro
