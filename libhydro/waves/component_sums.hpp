#pragma once
// The linear kinematics of a sum of wave components at one point (wave_component.hpp gives one
// component's; docs/theory.md the theory), over the components' terms laid out one array per term, so
// that the loops over the components vectorise: the phases' cosines and sines and the depth
// factors' exponentials through vector_math.hpp, the sums as SIMD reductions (compiled with
// -fopenmp-simd). A 200-component sea costs about a third of what one component after another
// did (docs/performance.md); the sums' order differs, so their last bits do.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

// The ComponentTerms of every component, one array per term.
struct ComponentTable {
  std::vector<double> kx, ky, k, omega, phase, amplitude, velocity, acceleration, pressure;
  std::vector<double> bed, over_sinh, over_cosh;
  std::vector<double> dx, dy, dxx, dxy, dyy;  // the heading's direction d and its products
  // k times amplitude, velocity, acceleration and pressure (long_crested_sums.hpp)
  std::vector<double> k_amplitude, k_velocity, k_acceleration, k_pressure;
  bool k_ascending = true;  // k never decreases from one component to the next
  void add(const ComponentTerms& c);
  std::size_t size() const { return k.size(); }
};

// One point's work per component: the phase theta, its cosine and sine, the envelope (value,
// rate, slope and rate_slope of Envelope; the caller fills them), the depth factor e^{k z}, and
// the fifteen terms a component adds to the kinematics and their gradients.
struct ComponentScratch {
  std::vector<double> theta, cos, sin, value, rate, slope, rate_slope, kz, ekz, terms;
  void resize(std::size_t n);
};

// theta_i = kx_i x + ky_i y - omega_i t + phi_i, with its cosine and sine, into s.
void componentPhases(const ComponentTable& c, const Eigen::Vector3d& x, double t,
                     ComponentScratch& s);
// The elevation, sum of E_i a_i cos(theta_i), and with `gradient` its horizontal gradient (the
// envelope's slope along each heading and the phase's wave number).
double elevationSum(const ComponentTable& c, const ComponentScratch& s, Eigen::Vector3d* gradient);
// The kinematics at depth z (z <= 0; the phases and envelopes in s), and with `gradients` their
// partial derivatives, into `out` (which they replace).
void kinematicsSum(const ComponentTable& c, ComponentScratch& s, double z, bool gradients,
                   LinearKinematics& out);

}  // namespace flexmoor::hydro
