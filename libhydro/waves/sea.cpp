#include "libhydro/waves/sea.hpp"

#include <algorithm>
#include <cmath>

namespace flexmoor::hydro {

void Sea::addComponent(const WaveComponent& c) {
  components_.push_back(c);
  terms_.push_back(ComponentTerms::of(c, water_.depth, water_.density, water_.gravity));
  if (front_) fronts_.push_back(componentFront(*front_, c, water_.depth, water_.gravity));
}

void Sea::setFront(const WaveFront& front) {
  front_ = front;
  fronts_.clear();
  for (const WaveComponent& c : components_)
    fronts_.push_back(componentFront(front, c, water_.depth, water_.gravity));
}

Envelope Sea::envelope(int c, const Eigen::Vector3d& x, double t) const {
  if (!front_) return {};
  const Eigen::Vector3d& d = terms_[c].direction;
  return frontEnvelope(fronts_[c], x.x() * d.x() + x.y() * d.y(), t);
}

double Sea::phases(const Eigen::Vector3d& x, double t, std::vector<Phase>& out,
                   Eigen::Vector3d* elevation_gradient) const {
  out.resize(terms_.size());
  const Envelope ramp = ramp_ ? rampEnvelope(*ramp_, t) : Envelope();
  double eta = 0.0;
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const ComponentTerms& c = terms_[i];
    Phase& p = out[i];
    const double th = c.theta(x, t);
    p.cos_th = std::cos(th);
    p.sin_th = std::sin(th);
    p.envelope = envelope(static_cast<int>(i), x, t);
    if (ramp_) p.envelope = product(p.envelope, ramp);
    const double e = p.envelope.value;
    eta += e * c.amplitude * p.cos_th;
    if (elevation_gradient) {
      // d/dx of E a cos(theta): the ramp's slope along the heading and the phase's k.
      elevation_gradient->x() +=
          c.amplitude * (p.envelope.slope * c.direction.x() * p.cos_th - e * c.kx * p.sin_th);
      elevation_gradient->y() +=
          c.amplitude * (p.envelope.slope * c.direction.y() * p.cos_th - e * c.ky * p.sin_th);
    }
  }
  return eta;
}

double Sea::elevation(const Eigen::Vector3d& x, double t) const {
  thread_local std::vector<Phase> scratch;
  return phases(x, t, scratch, nullptr);
}

FluidPoint Sea::evaluate(const Eigen::Vector3d& x, double t, FluidGradient* gradient) const {
  thread_local std::vector<Phase> scratch;
  FluidPoint p;
  if (gradient) *gradient = FluidGradient();
  p.elevation = phases(x, t, scratch, gradient ? &gradient->elevation : nullptr);
  p.wet = x.z() <= p.elevation;
  if (!p.wet) return p;
  const double h = water_.depth, eta = p.elevation;
  // Where linear theory is evaluated, and d z' / d(x, y, z): Wheeler maps [-h, eta] onto
  // [-h, 0]; constant extrapolation holds z' = 0 above the mean level.
  double z = std::min(x.z(), 0.0);
  Eigen::Vector3d dz(0.0, 0.0, x.z() < 0.0 ? 1.0 : 0.0);
  if (surface_ == SurfaceKinematics::Wheeler) {
    if (std::isinf(h)) {
      z = x.z() - eta;
      dz = Eigen::Vector3d(0.0, 0.0, 1.0);
      if (gradient) dz.head<2>() = -gradient->elevation.head<2>();
    } else {
      z = h * (x.z() - eta) / (h + eta);
      dz = Eigen::Vector3d(0.0, 0.0, h / (h + eta));
      if (gradient)
        dz.head<2>() = -h * (h + x.z()) / ((h + eta) * (h + eta)) * gradient->elevation.head<2>();
    }
  }
  LinearKinematics k;
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const Phase& ph = scratch[i];
    if (ph.envelope.value == 0.0 && ph.envelope.rate == 0.0) continue;  // ahead of the front
    addComponentKinematics(terms_[i], z, ph.cos_th, ph.sin_th, ph.envelope, gradient != nullptr, k);
  }
  const double rho_g = water_.density * water_.gravity;
  p.velocity = k.velocity + current_.velocity(z);
  p.acceleration = k.acceleration;
  p.pressure = -rho_g * x.z() + k.dynamic_pressure;
  if (!gradient) return p;
  // The chain rule through z'(x, y, z): d/dy_j = partial_j + partial_z' dz'/dy_j.
  for (int j = 0; j < 2; ++j) {
    gradient->velocity.col(j) = k.velocity_xy.col(j);
    gradient->acceleration.col(j) = k.acceleration_xy.col(j);
    gradient->pressure(j) = k.pressure_xy(j);
  }
  gradient->velocity += (k.velocity_z + current_.velocityShear(z)) * dz.transpose();
  gradient->acceleration += k.acceleration_z * dz.transpose();
  gradient->pressure += k.pressure_z * dz;
  gradient->pressure.z() -= rho_g;
  return p;
}

}  // namespace flexmoor::hydro
