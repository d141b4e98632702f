#include "libhydro/waves/held_kinematics.hpp"

#include <stdexcept>
#include <utility>

namespace flexmoor::hydro {
namespace {

constexpr size_t kMaxHeld = 64;  // points held per key

}  // namespace

HeldKinematics::HeldKinematics(std::shared_ptr<const Sea> sea, double radius)
    : sea_(std::move(sea)), radius_(radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("HeldKinematics: needs a radius > 0");
}

FluidPoint HeldKinematics::at(int key, const Eigen::Vector3d& x, double t,
                              FluidGradient& gradient) const {
  std::lock_guard<std::mutex> guard(lock_);
  if (!any_ || t != t_) {
    held_.clear();
    t_ = t;
    any_ = true;
  }
  std::vector<Held>& group = held_[key];
  const Held* nearest = nullptr;
  double best = radius_;
  for (const Held& h : group)
    if (const double d = (x - h.x).norm(); d <= best) {
      best = d;
      nearest = &h;
    }
  if (nearest) {
    const Eigen::Vector3d dx = x - nearest->x;
    const FluidGradient& g = nearest->gradient;
    FluidPoint f;
    f.elevation = nearest->flow.elevation + g.elevation.dot(dx);
    f.wet = x.z() <= f.elevation;
    if (f.wet == nearest->flow.wet) {
      ++counts_.reuses;
      gradient = g;
      if (!f.wet) return f;  // dry: nothing but the elevation
      f.velocity = nearest->flow.velocity + g.velocity * dx;
      f.acceleration = nearest->flow.acceleration + g.acceleration * dx;
      f.pressure = nearest->flow.pressure + g.pressure.dot(dx);
      return f;
    }
  }
  ++counts_.evaluations;
  const FluidPoint f = sea_->at(x, t, gradient);
  // A group holds a few points (an element's integration points); one that keeps missing (a
  // static solve at one time, moving its points far) starts afresh rather than growing.
  if (group.size() >= kMaxHeld) group.clear();
  group.push_back({x, f, gradient});
  return f;
}

HeldKinematics::Counts HeldKinematics::counts() const {
  std::lock_guard<std::mutex> guard(lock_);
  return counts_;
}

}  // namespace flexmoor::hydro
