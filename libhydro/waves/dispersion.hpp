#pragma once
// Linear (Airy) wave dispersion at any depth: omega^2 = g k tanh(k h) (docs/theory.md), and the phase
// and group speeds that follow from it. Depth may be +infinity (deep water).
namespace flexmoor::hydro {

// The wave number k > 0 of circular frequency omega > 0 in water of depth h > 0 (or +inf) under
// gravity g > 0. Safeguarded Newton from an explicit start; the residual
// |omega^2 / (g k tanh(k h)) - 1| is below 1e-14 at every k h.
double waveNumber(double omega, double depth, double g);

// c = omega / k.
double phaseSpeed(double k, double depth, double g);

// c_g = d omega / d k = c / 2 (1 + 2 k h / sinh(2 k h)); c / 2 in deep water.
double groupSpeed(double k, double depth, double g);

}  // namespace flexmoor::hydro
