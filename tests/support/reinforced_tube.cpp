#include "tests/support/reinforced_tube.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "tests/support/scalar_root.hpp"

namespace flexmoor::test {

// ---- the membrane ---------------------------------------------------------------------------

double TubeMembraneLaw::energy(double r, double s) const {
  const double l1s = 1.0 + s * s, l2s = (r / R) * (r / R);
  const double I1 = l1s + l2s + 1.0 / (l1s * l2s);
  const double I2 = 1.0 / l1s + 1.0 / l2s + l1s * l2s;
  return R * h0 * (C1 * (I1 - 3.0) + C2 * (I2 - 3.0));
}

double TubeMembraneLaw::meridionalForce(double r, double s) const {
  const double l1s = 1.0 + s * s, l2s = (r / R) * (r / R);
  return 2.0 * R * h0 * s * (1.0 - 1.0 / (l1s * l1s * l2s)) * (C1 + C2 * l2s);
}

double TubeMembraneLaw::dForceDSlope(double r, double s) const {
  const double l1s = 1.0 + s * s, l2s = (r / R) * (r / R);
  const double a = 1.0 / (l1s * l1s);                 // l1^-4
  const double da_ds = -4.0 * s / (l1s * l1s * l1s);  // d(l1^-4)/ds
  const double f = (1.0 - a / l2s) * (C1 + C2 * l2s);
  const double df_ds = -da_ds / l2s * (C1 + C2 * l2s);
  return 2.0 * R * h0 * (f + s * df_ds);
}

double TubeMembraneLaw::dForceDRadius(double r, double s) const {
  const double l1s = 1.0 + s * s, l2 = r / R, l2s = l2 * l2;
  const double a = 1.0 / (l1s * l1s);
  // d/dl2 [(1 - a l2^-2)(C1 + C2 l2^2)], then dl2/dr = 1 / R.
  const double df_dl2 = 2.0 * a / (l2s * l2) * (C1 + C2 * l2s) + (1.0 - a / l2s) * 2.0 * C2 * l2;
  return 2.0 * h0 * s * df_dl2;
}

double TubeMembraneLaw::hoopForce(double r, double s) const {
  const double l1s = 1.0 + s * s, l2 = r / R;
  return 2.0 * h0 * (l2 - 1.0 / (l2 * l2 * l2 * l1s)) * (C1 + C2 * l1s);
}

// ---- the hoop cables ------------------------------------------------------------------------

double HoopRingLaw::energy(double r, double area) const {
  const double l = r / R;
  return R * area * (C1 * (l * l + 2.0 / l - 3.0) + C2 * (2.0 * l + 1.0 / (l * l) - 3.0));
}

double HoopRingLaw::inwardForce(double r, double area) const {
  const double l = r / R;
  return area * l * 2.0 * (1.0 - 1.0 / (l * l * l)) * (C1 + C2 / l);
}

namespace {

// Why an integration from a guessed r(0) stopped early: the tube shrank below its reference
// radius (the guess was too small) or blew up (too large).
enum class Escape { None, Collapsed, Burst };

struct Problem {
  TubeMembraneLaw membrane;
  HoopRingLaw ring;
  double pressure;
  Escape escape = Escape::None;
};

int derivatives(double, const double y[], double dydz[], void* params) {
  Problem& P = *static_cast<Problem*>(params);
  const double r = y[0], s = y[1], R = P.membrane.R;
  if (!(r > R) || !(s > -1e3)) {
    P.escape = Escape::Collapsed;
    return GSL_EBADFUNC;
  }
  if (!(r < 3.0 * R) || !(s < 1e3)) {
    P.escape = Escape::Burst;
    return GSL_EBADFUNC;
  }
  const double stiffness = P.membrane.dForceDSlope(r, s);
  if (!(stiffness > 0.0)) {  // a slack meridian: only near r = R, when the shot falls short
    P.escape = Escape::Collapsed;
    return GSL_EBADFUNC;
  }
  const double dq_dz = P.membrane.hoopForce(r, s) - P.pressure * r;
  dydz[0] = s;
  dydz[1] = (dq_dz - P.membrane.dForceDRadius(r, s) * s) / stiffness;
  return GSL_SUCCESS;
}

// The slope s at radius r (> R) whose meridional force is q: q(s) is odd and increasing in s.
double slopeForForce(const TubeMembraneLaw& m, double r, double q) {
  if (q == 0.0) return 0.0;
  double hi = 1.0;
  while (std::abs(m.meridionalForce(r, hi)) < std::abs(q)) hi *= 2.0;
  return findRoot([&](double s) { return m.meridionalForce(r, s) - q; }, -hi, hi);
}

struct Shot {
  Escape escape = Escape::None;
  double end_mismatch = 0.0;   // q(L) + A_L lambda S at the symmetry plane
  std::vector<double> radius;  // at the requested points
};

Shot shoot(const ReinforcedTubeInputs& in, double r0, const std::vector<double>& z) {
  Problem P{
      {in.radius, in.thickness, in.C1, in.C2}, {in.radius, in.cable_C1, in.cable_C2}, in.pressure};
  const auto ringArea = [&](double at) {
    double a = 0.0;
    for (const HoopRing& h : in.rings)
      if (h.z == at) a += h.area;
    return a;
  };
  // Stations: the ends, the rings and the requested points, in order.
  std::vector<double> stations = {0.0, in.length};
  for (const HoopRing& h : in.rings) stations.push_back(h.z);
  stations.insert(stations.end(), z.begin(), z.end());
  std::sort(stations.begin(), stations.end());
  stations.erase(std::unique(stations.begin(), stations.end()), stations.end());

  gsl_odeiv2_system system{derivatives, nullptr, 2, &P};
  const std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
      gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, 1e-3, 1e-14, 1e-12),
      &gsl_odeiv2_driver_free);
  Shot shot;
  double y[2] = {r0, slopeForForce(P.membrane, r0, P.ring.inwardForce(r0, ringArea(0.0)))};
  double at = 0.0;
  const gsl_error_handler_t* previous = gsl_set_error_handler_off();
  for (const double next : stations) {
    if (next > at) {
      const int status = gsl_odeiv2_driver_apply(driver.get(), &at, next, y);
      if (status != GSL_SUCCESS) {
        gsl_set_error_handler(previous);
        // A failure the derivatives did not flag (the step size underflowed): the direction the
        // meridian was heading in says which way the shot missed.
        shot.escape = P.escape != Escape::None ? P.escape
                      : y[1] < 0.0             ? Escape::Collapsed
                                               : Escape::Burst;
        return shot;
      }
    }
    if (std::find(z.begin(), z.end(), next) != z.end()) shot.radius.push_back(y[0]);
    const double area = ringArea(next);
    if (next > 0.0 && next < in.length && area > 0.0) {  // a jump of q at an interior ring
      const double q = P.membrane.meridionalForce(y[0], y[1]) + P.ring.inwardForce(y[0], area);
      y[1] = slopeForForce(P.membrane, y[0], q);
    }
  }
  gsl_set_error_handler(previous);
  shot.end_mismatch =
      P.membrane.meridionalForce(y[0], y[1]) + P.ring.inwardForce(y[0], ringArea(in.length));
  return shot;
}

}  // namespace

std::vector<double> reinforcedTubeDisplacements(const ReinforcedTubeInputs& in,
                                                const std::vector<double>& z) {
  std::vector<double> sorted = z;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  const auto mismatch = [&](double r0) {
    const Shot s = shoot(in, r0, sorted);
    if (s.escape == Escape::Collapsed) return -1e30;
    if (s.escape == Escape::Burst) return 1e30;
    return s.end_mismatch;
  };
  // Bracket: just above the reference radius, and the unreinforced tube (Green & Adkins) at
  // this pressure, p = 2 (C1 + C2)(h0 / R)(1 - lambda^-4).
  const double limit = 2.0 * (in.C1 + in.C2) * in.thickness / in.radius;
  if (!(in.pressure > 0.0 && in.pressure < limit))
    throw std::invalid_argument("reinforcedTubeDisplacements: pressure outside (0, p_lim)");
  const double unreinforced = in.radius * std::pow(1.0 - in.pressure / limit, -0.25);
  const double r0 = findRoot(mismatch, in.radius * (1.0 + 1e-9), unreinforced * (1.0 + 1e-6));
  const Shot s = shoot(in, r0, sorted);
  if (s.escape != Escape::None) throw std::runtime_error("reinforced tube: the shot escaped");
  std::vector<double> out;
  for (const double point : z) {
    const size_t k = std::lower_bound(sorted.begin(), sorted.end(), point) - sorted.begin();
    out.push_back(s.radius[k] - in.radius);
  }
  return out;
}

}  // namespace flexmoor::test
