#pragma once
// The seabed's height z_b(x, y) (z up): a flat bed at -h, a sloped plane, or a table on a regular
// grid interpolated bilinearly and held beyond its edges. Its upward unit normal comes from the
// height's gradient.
#include <Eigen/Core>
#include <vector>

namespace flexmoor::hydro {

class Bathymetry {
 public:
  static Bathymetry flat(double depth);
  // z_b = z0 + slope_x x + slope_y y.
  static Bathymetry plane(double z0, double slope_x, double slope_y);
  // Heights z_b[i + nx j] at x0 + i dx, y0 + j dy (nx, ny >= 2).
  static Bathymetry grid(double x0, double dx, int nx, double y0, double dy, int ny,
                         std::vector<double> heights);

  double height(double x, double y) const;
  Eigen::Vector2d gradient(double x, double y) const;
  Eigen::Vector3d normal(double x, double y) const;  // (-dz_b/dx, -dz_b/dy, 1) normalised

 private:
  enum class Kind { Plane, Grid };
  Kind kind_ = Kind::Plane;
  double z0_ = 0.0, slope_x_ = 0.0, slope_y_ = 0.0;
  double x0_ = 0.0, dx_ = 1.0, y0_ = 0.0, dy_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<double> heights_;
};

}  // namespace flexmoor::hydro
