#include "libhydro/waves/long_crested_sums.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libhydro/waves/vector_math.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kTiny = std::numeric_limits<double>::min();  // as in component_sums.cpp
constexpr double kLn2To60 = 41.58883083359672;                // ln(2^60)

}  // namespace

double longCrestedElevation(const ComponentTable& c, const ComponentScratch& s, const Envelope& e,
                            Eigen::Vector3d* gradient) {
  const std::size_t n = c.size();
  const double *a = c.amplitude.data(), *ka = c.k_amplitude.data();
  const double *co = s.cos.data(), *si = s.sin.data();
  double eta = 0.0, slope = 0.0;
#pragma omp simd reduction(+ : eta, slope)
  for (std::size_t i = 0; i < n; ++i) {
    eta += a[i] * co[i];
    slope += ka[i] * si[i];
  }
  if (gradient && n > 0) *gradient += -e.value * slope * Eigen::Vector3d(c.dx[0], c.dy[0], 0.0);
  return e.value * eta;
}

// The depth factors e^{kz} (1 + r) and e^{kz} (1 - r), r = e^{-2k(z + h)}, are at most
// 2 max(e^{kz}, e^{-k(z + 2h)}) = 2 e^{-k d}, d = min(-z, 2h + z) (the second below the bed,
// where a line resting on it may sink a little), times 1 / (1 - e^{-2kh}), which is below
// 1 + 2^-119 where k d >= ln(2^60) (k h >= k d): so each factor is below 2^-59 for k beyond.
std::size_t componentsFelt(const ComponentTable& c, double z, double depth) {
  const double d = std::isinf(depth) ? -z : std::min(-z, 2.0 * depth + z);
  if (!c.k_ascending || !(d > 0.0)) return c.size();
  const double k_cut = kLn2To60 / d;
  return static_cast<std::size_t>(std::lower_bound(c.k.begin(), c.k.end(), k_cut) - c.k.begin());
}

// With f_h, f_v, f_p as in kinematicsSum (component_sums.cpp), U = a w, A = a w^2, P = rho g a,
// the eleven sums
//   s1 = sum U f_h cos, s2 = sum U f_v sin, s3 = sum A f_h sin, s4 = sum A f_v cos,
//   s5 = sum k U f_h sin, s6 = sum k U f_v cos, s7 = sum k A f_h cos, s8 = sum k A f_v sin,
//   s9 = sum P f_p cos, s10 = sum k P f_p sin, s11 = sum k P (sinh / cosh) cos
// give, with E and E' the envelope: u = E s1 d, w = E s2; du/dt = (E s3 + E' s1) d, dw/dt =
// -E s4 + E' s2; p = E s9; d/dxi (xi along d) of u, w, du/dt, dw/dt, p: -E s5, E s6,
// E s7 - E' s5, E s8 + E' s6, -E s10; d/dz of the same: E s6, E s5, E s8 + E' s6,
// -E s7 + E' s5, E s11 (each a term of kinematicsSum's H, V, P, G and Z with slope 0).
void longCrestedKinematics(const ComponentTable& c, ComponentScratch& s, const Envelope& e,
                           double z, double depth, bool gradients, LinearKinematics& out) {
  const std::size_t n = componentsFelt(c, z, depth);
  out = LinearKinematics();
  if (c.size() == 0) return;  // no component, no heading
  for (std::size_t i = 0; i < n; ++i) s.kz[i] = c.k[i] * z;
  exponentials(s.kz.data(), s.ekz.data(), n);
  double* const t = s.terms.data();
  double *fh = t, *fv = t + n, *fp = t + 2 * n, *fpz = t + 3 * n;
  const double *ekz_ = s.ekz.data(), *bed = c.bed.data();
  const double *over_sinh = c.over_sinh.data(), *over_cosh = c.over_cosh.data();
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    const double ekz = ekz_[i], r = bed[i] / std::max(ekz * ekz, kTiny);
    const double cosh_ratio = ekz * (1.0 + r), sinh_ratio = ekz * (1.0 - r);
    fh[i] = cosh_ratio * over_sinh[i];
    fv[i] = sinh_ratio * over_sinh[i];
    fp[i] = cosh_ratio * over_cosh[i];
    fpz[i] = sinh_ratio * over_cosh[i];
  }
  const double *co = s.cos.data(), *si = s.sin.data();
  const double *U = c.velocity.data(), *A = c.acceleration.data(), *P = c.pressure.data();
  const double *kU = c.k_velocity.data(), *kA = c.k_acceleration.data();
  const double* kP = c.k_pressure.data();
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0, s9 = 0, s10 = 0, s11 = 0;
  if (!gradients) {
#pragma omp simd reduction(+ : s1, s2, s3, s4, s9)
    for (std::size_t i = 0; i < n; ++i) {
      s1 += U[i] * fh[i] * co[i];
      s2 += U[i] * fv[i] * si[i];
      s3 += A[i] * fh[i] * si[i];
      s4 += A[i] * fv[i] * co[i];
      s9 += P[i] * fp[i] * co[i];
    }
  } else {
    // Three passes of at most four reductions each keep the sums in registers.
#pragma omp simd reduction(+ : s1, s3, s5, s7)
    for (std::size_t i = 0; i < n; ++i) {
      const double hc = fh[i] * co[i], hs = fh[i] * si[i];
      s1 += U[i] * hc;
      s3 += A[i] * hs;
      s5 += kU[i] * hs;
      s7 += kA[i] * hc;
    }
#pragma omp simd reduction(+ : s2, s4, s6, s8)
    for (std::size_t i = 0; i < n; ++i) {
      const double vc = fv[i] * co[i], vs = fv[i] * si[i];
      s2 += U[i] * vs;
      s4 += A[i] * vc;
      s6 += kU[i] * vc;
      s8 += kA[i] * vs;
    }
#pragma omp simd reduction(+ : s9, s10, s11)
    for (std::size_t i = 0; i < n; ++i) {
      s9 += P[i] * fp[i] * co[i];
      s10 += kP[i] * fp[i] * si[i];
      s11 += kP[i] * fpz[i] * co[i];
    }
  }
  const double E = e.value, R = e.rate, dx = c.dx[0], dy = c.dy[0];
  const double u = E * s1, du = E * s3 + R * s1;
  out.velocity = {u * dx, u * dy, E * s2};
  out.acceleration = {du * dx, du * dy, -E * s4 + R * s2};
  out.dynamic_pressure = E * s9;
  if (!gradients) return;
  const double dxx = dx * dx, dxy = dx * dy, dyy = dy * dy;
  const double g1 = -E * s5, g2 = E * s7 - R * s5, g3 = E * s6, g4 = E * s8 + R * s6;
  out.velocity_xy << g1 * dxx, g1 * dxy, g1 * dxy, g1 * dyy, g3 * dx, g3 * dy;
  out.acceleration_xy << g2 * dxx, g2 * dxy, g2 * dxy, g2 * dyy, g4 * dx, g4 * dy;
  out.pressure_xy = {-E * s10 * dx, -E * s10 * dy};
  const double z1 = E * s6, z3 = E * s8 + R * s6;
  out.velocity_z = {z1 * dx, z1 * dy, E * s5};
  out.acceleration_z = {z3 * dx, z3 * dy, -E * s7 + R * s5};
  out.pressure_z = E * s11;
}

}  // namespace flexmoor::hydro
