#include "libhydro/waves/sea.hpp"

#include <algorithm>
#include <cmath>

namespace flexmoor::hydro {

Envelope Sea::envelope(const WaveComponent& c, const Eigen::Vector3d& x, double t) const {
  if (!front_) return {};
  return frontEnvelope(*front_, c, x.dot(c.direction()), t, water_.depth, water_.gravity);
}

double Sea::elevation(const Eigen::Vector3d& x, double t) const {
  double eta = 0.0;
  for (const WaveComponent& c : components_)
    eta += envelope(c, x, t).value * c.amplitude * std::cos(c.theta(x, t));
  return eta;
}

FluidPoint Sea::at(const Eigen::Vector3d& x, double t) const {
  FluidPoint p;
  p.elevation = elevation(x, t);
  p.wet = x.z() <= p.elevation;
  if (!p.wet) return p;
  const double h = water_.depth;
  // Where linear theory is evaluated: Wheeler maps [-h, eta] onto [-h, 0].
  double z = std::min(x.z(), 0.0);
  if (surface_ == SurfaceKinematics::Wheeler)
    z = std::isinf(h) ? x.z() - p.elevation : h * (x.z() - p.elevation) / (h + p.elevation);
  const Eigen::Vector3d at_z(x.x(), x.y(), z);
  LinearKinematics k;
  for (const WaveComponent& c : components_) {
    const Envelope e = envelope(c, x, t);
    if (e.value == 0.0 && e.rate == 0.0) continue;
    addComponentKinematics(c, at_z, t, h, water_.density, water_.gravity, e.value, e.rate, k);
  }
  p.velocity = k.velocity + current_.velocity(z);
  p.acceleration = k.acceleration;
  p.pressure = -water_.density * water_.gravity * x.z() + k.dynamic_pressure;
  return p;
}

}  // namespace flexmoor::hydro
