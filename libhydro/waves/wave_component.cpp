#include "libhydro/waves/wave_component.hpp"

#include <cmath>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {
namespace {

const double kTwoPi = 2.0 * std::acos(-1.0);

// Depth attenuation of the horizontal velocity cosh(k (z + h)) / sinh(k h), of the vertical
// sinh(k (z + h)) / sinh(k h) and of the pressure cosh(k (z + h)) / cosh(k h), written with
// exponentials so that deep water (h = inf, or k h large) does not overflow.
struct Attenuation {
  double horizontal, vertical, pressure;
};

Attenuation attenuation(double k, double z, double depth) {
  const double e = std::exp(k * z);  // z <= 0
  if (std::isinf(depth) || k * depth > 350.0) return {e, e, e};
  const double e2h = std::exp(-2.0 * k * depth);
  const double ez = std::exp(-2.0 * k * (z + depth));
  // cosh(k(z+h)) / sinh(k h) = e^{kz} (1 + e^{-2k(z+h)}) / (1 - e^{-2kh}), and so on.
  return {e * (1.0 + ez) / (1.0 - e2h), e * (1.0 - ez) / (1.0 - e2h), e * (1.0 + ez) / (1.0 + e2h)};
}

}  // namespace

WaveComponent WaveComponent::fromHeightAndPeriod(double height, double period, double heading,
                                                 double phase, double depth, double g) {
  WaveComponent c;
  c.amplitude = 0.5 * height;
  c.omega = kTwoPi / period;
  c.k = waveNumber(c.omega, depth, g);
  c.heading = heading;
  c.phase = phase;
  return c;
}

double WaveComponent::theta(const Eigen::Vector3d& x, double t) const {
  return k * (x.x() * std::cos(heading) + x.y() * std::sin(heading)) - omega * t + phase;
}

Eigen::Vector3d WaveComponent::direction() const {
  return {std::cos(heading), std::sin(heading), 0.0};
}

void addComponentKinematics(const WaveComponent& c, const Eigen::Vector3d& x, double t,
                            double depth, double rho, double g, double envelope,
                            double envelope_rate, LinearKinematics& out) {
  const double th = c.theta(x, t), cos_th = std::cos(th), sin_th = std::sin(th);
  const Attenuation f = attenuation(c.k, x.z(), depth);
  const double aw = c.amplitude * c.omega;
  // u = a w f_h cos(theta) along the heading, w = a w f_v sin(theta) (hydro.md).
  const double u = aw * f.horizontal * cos_th, w = aw * f.vertical * sin_th;
  // Local accelerations: du/dt = a w^2 f_h sin(theta), dw/dt = -a w^2 f_v cos(theta).
  const double du = aw * c.omega * f.horizontal * sin_th;
  const double dw = -aw * c.omega * f.vertical * cos_th;
  const Eigen::Vector3d e = c.direction();
  out.velocity += envelope * (u * e + w * Eigen::Vector3d::UnitZ());
  out.acceleration += envelope * (du * e + dw * Eigen::Vector3d::UnitZ()) +
                      envelope_rate * (u * e + w * Eigen::Vector3d::UnitZ());
  // p_dyn = rho g a cosh(k (z + h)) / cosh(k h) cos(theta).
  out.dynamic_pressure += envelope * rho * g * c.amplitude * f.pressure * cos_th;
}

}  // namespace flexmoor::hydro
