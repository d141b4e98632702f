#include "libhydro/water/current_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexmoor::hydro {
namespace {

Eigen::Vector3d horizontal(double heading) { return {std::cos(heading), std::sin(heading), 0.0}; }

}  // namespace

CurrentProfile CurrentProfile::none() { return uniform(0.0, 0.0); }

CurrentProfile CurrentProfile::uniform(double speed, double heading) {
  CurrentProfile c;
  c.speed_ = speed;
  c.direction_ = horizontal(heading);
  return c;
}

CurrentProfile CurrentProfile::powerLaw(double surface_speed, double exponent_n, double depth,
                                        double heading) {
  if (!(exponent_n > 0.0) || !(depth > 0.0) || std::isinf(depth))
    throw std::invalid_argument("power-law current: needs n > 0 and a finite depth > 0");
  CurrentProfile c = uniform(surface_speed, heading);
  c.kind_ = Kind::PowerLaw;
  c.exponent_n_ = exponent_n;
  c.depth_ = depth;
  return c;
}

CurrentProfile CurrentProfile::table(std::vector<std::pair<double, double>> samples,
                                     double heading) {
  if (samples.empty()) throw std::invalid_argument("tabulated current: no samples");
  for (size_t i = 1; i < samples.size(); ++i)
    if (!(samples[i].first > samples[i - 1].first))
      throw std::invalid_argument("tabulated current: z must increase strictly");
  CurrentProfile c = uniform(0.0, heading);
  c.kind_ = Kind::Table;
  c.samples_ = std::move(samples);
  return c;
}

double CurrentProfile::speed(double z) const {
  z = std::min(z, 0.0);
  switch (kind_) {
    case Kind::Uniform:
      return speed_;
    case Kind::PowerLaw:
      return speed_ * std::pow(std::max(0.0, (z + depth_) / depth_), 1.0 / exponent_n_);
    case Kind::Table: {
      if (z <= samples_.front().first) return samples_.front().second;
      if (z >= samples_.back().first) return samples_.back().second;
      const auto above = std::upper_bound(
          samples_.begin(), samples_.end(), z,
          [](double value, const std::pair<double, double>& s) { return value < s.first; });
      const auto below = above - 1;
      const double s = (z - below->first) / (above->first - below->first);
      return (1.0 - s) * below->second + s * above->second;
    }
  }
  return 0.0;
}

// dU/dz of speed(z): zero above the mean level and beyond a table's ends; a table's segment
// slope (the upper segment at a sample); a power law's U_s / (n h) ((z + h) / h)^(1/n - 1),
// singular at the bed, where (and below) it is taken as zero, as the speed is.
double CurrentProfile::shear(double z) const {
  if (z > 0.0) return 0.0;
  switch (kind_) {
    case Kind::Uniform:
      return 0.0;
    case Kind::PowerLaw: {
      const double s = (z + depth_) / depth_;
      if (s <= 0.0) return 0.0;
      return speed_ / (exponent_n_ * depth_) * std::pow(s, 1.0 / exponent_n_ - 1.0);
    }
    case Kind::Table: {
      if (z < samples_.front().first || z >= samples_.back().first) return 0.0;
      const auto above = std::upper_bound(
          samples_.begin(), samples_.end(), z,
          [](double value, const std::pair<double, double>& s) { return value < s.first; });
      const auto below = above - 1;
      return (above->second - below->second) / (above->first - below->first);
    }
  }
  return 0.0;
}

}  // namespace flexmoor::hydro
