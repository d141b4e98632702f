#include "libhydro/seabed/bathymetry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexmoor::hydro {

Bathymetry Bathymetry::flat(double depth) { return plane(-depth, 0.0, 0.0); }

Bathymetry Bathymetry::plane(double z0, double slope_x, double slope_y) {
  Bathymetry b;
  b.z0_ = z0;
  b.slope_x_ = slope_x;
  b.slope_y_ = slope_y;
  return b;
}

Bathymetry Bathymetry::grid(double x0, double dx, int nx, double y0, double dy, int ny,
                            std::vector<double> heights) {
  if (nx < 2 || ny < 2 || !(dx > 0.0) || !(dy > 0.0) ||
      heights.size() != static_cast<size_t>(nx) * ny)
    throw std::invalid_argument("bathymetry grid: needs nx, ny >= 2, dx, dy > 0, nx ny heights");
  Bathymetry b;
  b.kind_ = Kind::Grid;
  b.x0_ = x0, b.dx_ = dx, b.nx_ = nx, b.y0_ = y0, b.dy_ = dy, b.ny_ = ny;
  b.heights_ = std::move(heights);
  return b;
}

namespace {

// Cell index and local coordinate in [0, 1] of `x` on a grid, held at the edges.
void locate(double x, double x0, double dx, int n, int& i, double& s) {
  const double u = std::clamp((x - x0) / dx, 0.0, static_cast<double>(n - 1));
  i = std::min(static_cast<int>(u), n - 2);
  s = u - i;
}

}  // namespace

double Bathymetry::height(double x, double y) const {
  if (kind_ == Kind::Plane) return z0_ + slope_x_ * x + slope_y_ * y;
  int i, j;
  double s, t;
  locate(x, x0_, dx_, nx_, i, s);
  locate(y, y0_, dy_, ny_, j, t);
  const auto z = [&](int a, int b) { return heights_[(i + a) + nx_ * (j + b)]; };
  return (1 - s) * (1 - t) * z(0, 0) + s * (1 - t) * z(1, 0) + (1 - s) * t * z(0, 1) +
         s * t * z(1, 1);
}

Eigen::Vector2d Bathymetry::gradient(double x, double y) const {
  if (kind_ == Kind::Plane) return {slope_x_, slope_y_};
  int i, j;
  double s, t;
  locate(x, x0_, dx_, nx_, i, s);
  locate(y, y0_, dy_, ny_, j, t);
  const auto z = [&](int a, int b) { return heights_[(i + a) + nx_ * (j + b)]; };
  const bool inside_x = x > x0_ && x < x0_ + (nx_ - 1) * dx_;
  const bool inside_y = y > y0_ && y < y0_ + (ny_ - 1) * dy_;
  const double gx = ((1 - t) * (z(1, 0) - z(0, 0)) + t * (z(1, 1) - z(0, 1))) / dx_;
  const double gy = ((1 - s) * (z(0, 1) - z(0, 0)) + s * (z(1, 1) - z(1, 0))) / dy_;
  return {inside_x ? gx : 0.0, inside_y ? gy : 0.0};
}

Eigen::Vector3d Bathymetry::normal(double x, double y) const {
  const Eigen::Vector2d g = gradient(x, y);
  return Eigen::Vector3d(-g.x(), -g.y(), 1.0).normalized();
}

}  // namespace flexmoor::hydro
