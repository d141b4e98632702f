#include "libhydro/waves/sea.hpp"

#include <algorithm>
#include <cmath>

#include "libhydro/waves/long_crested_sums.hpp"

namespace flexmoor::hydro {

void Sea::addComponent(const WaveComponent& c) {
  components_.push_back(c);
  const ComponentTerms terms = ComponentTerms::of(c, water_.depth, water_.density, water_.gravity);
  if (table_.size() > 0 &&
      (terms.direction.x() != table_.dx[0] || terms.direction.y() != table_.dy[0]))
    long_crested_ = false;
  table_.add(terms);
  if (front_) fronts_.push_back(componentFront(*front_, c, water_.depth, water_.gravity));
}

void Sea::setFront(const WaveFront& front) {
  front_ = front;
  fronts_.clear();
  for (const WaveComponent& c : components_)
    fronts_.push_back(componentFront(front, c, water_.depth, water_.gravity));
}

Envelope Sea::rampAt(double t) const { return ramp_ ? rampEnvelope(*ramp_, t) : Envelope(); }

// The components' phases and envelopes at x, t into s (the front's per component along its
// heading, times the ramp's; with one envelope for all, the ramp's alone, not written out), and
// the elevation with its gradient.
double Sea::phases(const Eigen::Vector3d& x, double t, ComponentScratch& s,
                   Eigen::Vector3d* elevation_gradient) const {
  componentPhases(table_, x, t, s);
  const Envelope ramp = rampAt(t);
  if (oneEnvelope()) return longCrestedElevation(table_, s, ramp, elevation_gradient);
  for (std::size_t i = 0; i < table_.size(); ++i) {
    Envelope e = ramp;
    if (front_)
      e = product(frontEnvelope(fronts_[i], x.x() * table_.dx[i] + x.y() * table_.dy[i], t), ramp);
    s.value[i] = e.value;
    s.rate[i] = e.rate;
    s.slope[i] = e.slope;
    s.rate_slope[i] = e.rate_slope;
  }
  return elevationSum(table_, s, elevation_gradient);
}

double Sea::elevation(const Eigen::Vector3d& x, double t) const {
  thread_local ComponentScratch scratch;
  return phases(x, t, scratch, nullptr);
}

FluidPoint Sea::evaluate(const Eigen::Vector3d& x, double t, FluidGradient* gradient) const {
  thread_local ComponentScratch scratch;
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
  if (oneEnvelope())
    longCrestedKinematics(table_, scratch, rampAt(t), z, water_.depth, gradient != nullptr, k);
  else
    kinematicsSum(table_, scratch, z, gradient != nullptr, k);
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
