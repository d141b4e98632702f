#pragma once
// Extreme-value statistics of a stationary record: the most probable maximum (MPM) of the
// process over a duration D (usually longer than the record), from a fit to the record's peaks
// (Weibull) or to the maxima of its blocks (Gumbel). Plain C++ (no FFTW).
//   Mean up-crossings: samples i with x_{i-1} <= mean < x_i, the mean the record's; their times
//     interpolated linearly; Tz = (t_last - t_first) / (count - 1), the mean zero-up-crossing
//     period about the mean.
//   Weibull: the peaks are the largest sample between successive up-crossings (count - 1 of
//     them, each above the mean); their heights h = x - mean fitted by a 2-parameter Weibull
//     F(h) = 1 - exp(-(h / scale)^shape) (location at the mean) by least squares on the Weibull
//     plot, ln(-ln(1 - p_i)) = shape ln h_i - shape ln scale, p_i = i / (n + 1) the plotting
//     position of the i-th smallest of n, over the upper half of the peaks (p_i >= 1/2): the tail
//     sets the maximum, and a broad-band record's many small peaks near the mean (riding waves
//     that cross it) would bend a fit of all of them (shape 1.74 and an MPM 11% high on the test's
//     JONSWAP record; the upper half: within 1%). D holds N = D / Tz peaks; the largest of N
//     most probably takes the value where 1 - F = 1 / N (the mode of F^N for large N):
//       MPM = mean + scale (ln N)^(1 / shape).
//     A Gaussian process's peaks are Rayleigh (shape 2, scale sqrt(2) sigma): MPM = mean +
//     sigma sqrt(2 ln(D / Tz)).
//   Gumbel: the maxima of consecutive blocks of kGumbelBlockPeriods Tz (a whole number of
//     samples; the samples after the last whole block left out), fitted by the method of
//     moments: G(x) = exp(-exp(-(x - mu) / beta)), beta = sqrt(6) s / pi, mu = mean - gamma_E
//     beta (s the maxima's standard deviation, gamma_E Euler's constant). The maximum over D =
//     n blocks is Gumbel (mu + beta ln n, beta), whose mode is
//       MPM = mu + beta ln(D / T_block).
#include <vector>

namespace flexmoor::signal {

enum class ExtremeFit { Weibull, Gumbel };

// The fewest peaks a Weibull fit takes, and the fewest blocks a Gumbel fit takes.
inline constexpr int kMinimumPeaks = 30;
inline constexpr int kMinimumBlocks = 10;
// A Gumbel block's length in mean zero-up-crossing periods.
inline constexpr double kGumbelBlockPeriods = 20.0;

struct UpcrossingPeaks {
  double mean = 0.0;                    // the record's mean
  double zero_upcrossing_period = 0.0;  // Tz about the mean, s
  std::vector<double> peaks;            // the largest sample between successive up-crossings
};

struct WeibullParameters {
  double scale = 0.0, shape = 0.0;  // F(h) = 1 - exp(-(h / scale)^shape)
};

struct GumbelParameters {
  double location = 0.0, scale = 0.0;  // mu, beta: G(x) = exp(-exp(-(x - mu) / beta))
};

struct ExtremeEstimate {
  double mpm = 0.0;                     // the most probable maximum over the duration
  double mean = 0.0;                    // the record's mean
  double zero_upcrossing_period = 0.0;  // Tz, s
  int fitted = 0;                       // peaks (Weibull) or blocks (Gumbel) fitted
  double block_length = 0.0;            // Gumbel: the block's length, s; 0 for Weibull
  WeibullParameters weibull;            // Weibull: of the peaks' heights above the mean
  GumbelParameters gumbel;              // Gumbel: of the block maxima
};

// The record's mean, Tz and peaks. record.size() >= 2, dt > 0 (std::invalid_argument).
UpcrossingPeaks upcrossingPeaks(const std::vector<double>& record, double dt);

// The fraction of the peaks below the Weibull fit's: p_i >= kWeibullTailFrom are fitted.
inline constexpr double kWeibullTailFrom = 0.5;

// Least squares on the Weibull plot of the heights whose plotting position i / (n + 1) is at
// least `tail_from` (0: all of them): at least 2 of them, each > 0, not all equal
// (std::invalid_argument otherwise).
WeibullParameters fitWeibull(const std::vector<double>& heights, double tail_from);

// The method of moments' Gumbel of `maxima` (at least 2, not all equal).
GumbelParameters fitGumbel(const std::vector<double>& maxima);

// The fit and its MPM over `duration` (s). std::invalid_argument when dt or duration is not
// positive, when the record has fewer than kMinimumPeaks peaks (Weibull) or kMinimumBlocks
// blocks (Gumbel), or when the duration is shorter than Tz (Weibull) or a block (Gumbel).
ExtremeEstimate estimateExtremes(const std::vector<double>& record, double dt, double duration,
                                 ExtremeFit fit);

// The most probable maximum of the process over `duration` (s) from a record sampled at dt:
// estimateExtremes(...).mpm.
double mostProbableMaximum(const std::vector<double>& record, double dt, double duration,
                           ExtremeFit fit);

}  // namespace flexmoor::signal
