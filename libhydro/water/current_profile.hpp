#pragma once
// A steady current U(z) along a horizontal heading (docs/theory.md): uniform, a power law from the bed
// (U_s ((z + h) / h)^(1/n)), or a table of (z, U) interpolated linearly and held constant beyond
// its ends. Above the mean level the current is that at z = 0.
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace flexmoor::hydro {

class CurrentProfile {
 public:
  static CurrentProfile none();
  static CurrentProfile uniform(double speed, double heading);
  static CurrentProfile powerLaw(double surface_speed, double exponent_n, double depth,
                                 double heading);
  // (z, U) pairs in strictly increasing z.
  static CurrentProfile table(std::vector<std::pair<double, double>> samples, double heading);

  double speed(double z) const;
  Eigen::Vector3d velocity(double z) const { return speed(z) * direction_; }
  double shear(double z) const;  // d speed / dz
  Eigen::Vector3d velocityShear(double z) const { return shear(z) * direction_; }

 private:
  enum class Kind { Uniform, PowerLaw, Table };
  Kind kind_ = Kind::Uniform;
  double speed_ = 0.0, exponent_n_ = 7.0, depth_ = 0.0;
  std::vector<std::pair<double, double>> samples_;
  Eigen::Vector3d direction_ = Eigen::Vector3d::UnitX();
};

}  // namespace flexmoor::hydro
