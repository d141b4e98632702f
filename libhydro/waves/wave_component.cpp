#include "libhydro/waves/wave_component.hpp"

#include <cmath>

#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::hydro {
namespace {

const double kTwoPi = 2.0 * std::acos(-1.0);

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

ComponentTerms ComponentTerms::of(const WaveComponent& c, double depth, double rho, double g) {
  ComponentTerms t;
  t.direction = c.direction();
  t.kx = c.k * t.direction.x();
  t.ky = c.k * t.direction.y();
  t.k = c.k;
  t.omega = c.omega;
  t.phase = c.phase;
  t.amplitude = c.amplitude;
  t.velocity = c.amplitude * c.omega;
  t.acceleration = t.velocity * c.omega;
  t.pressure = rho * g * c.amplitude;
  if (!std::isinf(depth) && c.k * depth <= 350.0) {
    t.bed = std::exp(-2.0 * c.k * depth);
    t.over_sinh = 1.0 / (1.0 - t.bed);
    t.over_cosh = 1.0 / (1.0 + t.bed);
  }
  return t;
}

void addComponentKinematics(const ComponentTerms& c, double z, double cos_th, double sin_th,
                            const Envelope& e, bool gradients, LinearKinematics& out) {
  // e^{kz} and r = e^{-2k(z+h)}: cosh(k(z+h)) = e^{k(z+h)} (1 + r) / 2, and so on (z <= 0, so
  // that r <= 1 and deep water cannot overflow).
  const double ekz = std::exp(c.k * z), r = c.bed / (ekz * ekz);
  const double cosh_ratio = ekz * (1.0 + r), sinh_ratio = ekz * (1.0 - r);
  const double f_h = cosh_ratio * c.over_sinh;  // cosh(k (z + h)) / sinh(k h)
  const double f_v = sinh_ratio * c.over_sinh;  // sinh(k (z + h)) / sinh(k h)
  const double f_p = cosh_ratio * c.over_cosh;  // cosh(k (z + h)) / cosh(k h)
  const Eigen::Vector3d& d = c.direction;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  // u = a w f_h cos(theta) along the heading, w = a w f_v sin(theta) (hydro.md); local
  // accelerations du/dt = a w^2 f_h sin(theta), dw/dt = -a w^2 f_v cos(theta).
  const Eigen::Vector3d v = c.velocity * (f_h * cos_th * d + f_v * sin_th * up);
  const Eigen::Vector3d a = c.acceleration * (f_h * sin_th * d - f_v * cos_th * up);
  // p_dyn = rho g a cosh(k (z + h)) / cosh(k h) cos(theta).
  const double p = c.pressure * f_p * cos_th;
  out.velocity += e.value * v;
  out.acceleration += e.value * a + e.rate * v;
  out.dynamic_pressure += e.value * p;
  if (!gradients) return;
  // d/dtheta, times d theta / dx = k cos beta, d theta / dy = k sin beta; the envelope's slope
  // along the heading (d xi / dx = cos beta, d xi / dy = sin beta).
  const Eigen::Vector3d v_th = c.velocity * (-f_h * sin_th * d + f_v * cos_th * up);
  const Eigen::Vector3d a_th = c.acceleration * (f_h * cos_th * d + f_v * sin_th * up);
  const double p_th = -c.pressure * f_p * sin_th;
  const double k_xy[2] = {c.kx, c.ky};
  for (int i = 0; i < 2; ++i) {
    out.velocity_xy.col(i) += e.slope * d(i) * v + e.value * k_xy[i] * v_th;
    out.acceleration_xy.col(i) += e.slope * d(i) * a + e.value * k_xy[i] * a_th +
                                  e.rate_slope * d(i) * v + e.rate * k_xy[i] * v_th;
    out.pressure_xy(i) += e.slope * d(i) * p + e.value * k_xy[i] * p_th;
  }
  // d/dz: d f_h / dz = k f_v, d f_v / dz = k f_h, d f_p / dz = k sinh(k (z + h)) / cosh(k h).
  const Eigen::Vector3d v_z = c.k * c.velocity * (f_v * cos_th * d + f_h * sin_th * up);
  const Eigen::Vector3d a_z = c.k * c.acceleration * (f_v * sin_th * d - f_h * cos_th * up);
  out.velocity_z += e.value * v_z;
  out.acceleration_z += e.value * a_z + e.rate * v_z;
  out.pressure_z += e.value * c.k * c.pressure * sinh_ratio * c.over_cosh * cos_th;
}

}  // namespace flexmoor::hydro
