#pragma once
// Directional spreading of a short-crested sea, the cos-2s form (Longuet-Higgins et al. 1963;
// DNV-RP-C205 3.5.8):
//   D(beta) = C(s) cos^(2s)((beta - beta0) / 2), beta - beta0 in [-pi, pi],
//   C(s) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)), so that int D = 1,
// whose circular moments are closed forms: int D cos(beta - beta0) = s / (s + 1) (r1), int D
// cos 2(beta - beta0) = s (s - 1) / ((s + 1) (s + 2)), the sines zero (mean direction beta0), and
// the circular spread sqrt(2 (1 - r1)) = sqrt(2 / (s + 1)) (Kuik et al. 1988).
//
// Its discretisation: `directions` equal bins over beta0 +- W, W the half-width outside which D
// holds less than 1e-4 of the energy (pi when the whole circle is needed), each at its centre with
// the weight int_bin D, the weights scaled to sum to 1. A spectrum's component of amplitude a
// becomes one component a sqrt(w_j) per direction (the double sum).
#include <cmath>
#include <vector>

namespace flexmoor::hydro {

class CosineSpreading {
 public:
  CosineSpreading(double s, double mean_heading);  // s > 0

  double density(double heading) const;  // D(beta)
  double s() const { return s_; }
  double meanHeading() const { return mean_; }
  // Closed forms.
  double firstMoment() const { return s_ / (s_ + 1.0); }  // r1
  double secondMoment() const { return s_ * (s_ - 1.0) / ((s_ + 1.0) * (s_ + 2.0)); }
  double circularSpread() const { return std::sqrt(2.0 / (s_ + 1.0)); }
  // The half-width W outside which D holds less than `tail` of the energy (at most pi).
  double halfWidth(double tail) const;

 private:
  double s_, mean_, normaliser_;
};

struct Direction {
  double heading = 0.0;  // rad
  double weight = 0.0;   // share of the energy; the weights sum to 1
};

// directions >= 1; one direction is the mean heading with weight 1 (a long-crested sea).
std::vector<Direction> discretise(const CosineSpreading& spreading, int directions);

}  // namespace flexmoor::hydro
