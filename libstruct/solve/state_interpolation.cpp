#include "libstruct/solve/state_interpolation.hpp"

namespace flexmoor::solve {

model::State interpolate(const model::State& a, const model::State& b, double t) {
  const double h = b.time - a.time;
  const double s = (t - a.time) / h, s2 = s * s, s3 = s2 * s;
  // The Hermite basis on [0, 1] and its derivatives (d/dt = d/ds / h).
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
               h11 = s3 - s2;
  const double d00 = (6 * s2 - 6 * s) / h, d10 = 3 * s2 - 4 * s + 1, d01 = (-6 * s2 + 6 * s) / h,
               d11 = 3 * s2 - 2 * s;
  model::State x(static_cast<int>(a.displacement.cols()));
  x.displacement =
      h00 * a.displacement + (h10 * h) * a.velocity + h01 * b.displacement + (h11 * h) * b.velocity;
  x.velocity = d00 * a.displacement + d10 * a.velocity + d01 * b.displacement + d11 * b.velocity;
  x.acceleration = (1.0 - s) * a.acceleration + s * b.acceleration;
  x.time = t;
  x.load_factor = b.load_factor;
  x.still = b.still;
  return x;
}

}  // namespace flexmoor::solve
