#include "libhydro/waves/component_sums.hpp"

#include <algorithm>
#include <limits>

#include "libhydro/waves/vector_math.hpp"

namespace flexmoor::hydro {
namespace {

// The floor of e^{2kz} in r = bed / e^{2kz}: a maximum the loops vectorise, where a test for
// bed = 0 would keep them scalar (a division the compiler may not speculate).
constexpr double kTiny = std::numeric_limits<double>::min();

}  // namespace

void ComponentTable::add(const ComponentTerms& c) {
  if (!k.empty() && c.k < k.back()) k_ascending = false;
  kx.push_back(c.kx);
  ky.push_back(c.ky);
  k.push_back(c.k);
  omega.push_back(c.omega);
  phase.push_back(c.phase);
  amplitude.push_back(c.amplitude);
  velocity.push_back(c.velocity);
  acceleration.push_back(c.acceleration);
  pressure.push_back(c.pressure);
  bed.push_back(c.bed);
  over_sinh.push_back(c.over_sinh);
  over_cosh.push_back(c.over_cosh);
  dx.push_back(c.direction.x());
  dy.push_back(c.direction.y());
  dxx.push_back(c.direction.x() * c.direction.x());
  dxy.push_back(c.direction.x() * c.direction.y());
  dyy.push_back(c.direction.y() * c.direction.y());
  k_amplitude.push_back(c.k * c.amplitude);
  k_velocity.push_back(c.k * c.velocity);
  k_acceleration.push_back(c.k * c.acceleration);
  k_pressure.push_back(c.k * c.pressure);
}

void ComponentScratch::resize(std::size_t n) {
  for (std::vector<double>* v : {&theta, &cos, &sin, &value, &rate, &slope, &rate_slope, &kz, &ekz})
    v->resize(n);
  terms.resize(15 * n);
}

void componentPhases(const ComponentTable& c, const Eigen::Vector3d& x, double t,
                     ComponentScratch& s) {
  const std::size_t n = c.size();
  s.resize(n);
  const double px = x.x(), py = x.y();
  for (std::size_t i = 0; i < n; ++i)
    s.theta[i] = c.kx[i] * px + c.ky[i] * py - c.omega[i] * t + c.phase[i];
  cosinesAndSines(s.theta.data(), s.cos.data(), s.sin.data(), n);
}

double elevationSum(const ComponentTable& c, const ComponentScratch& s, Eigen::Vector3d* gradient) {
  const std::size_t n = c.size();
  double eta = 0.0, gx = 0.0, gy = 0.0;
#pragma omp simd reduction(+ : eta, gx, gy)
  for (std::size_t i = 0; i < n; ++i) {
    const double e = s.value[i], a = c.amplitude[i];
    eta += e * a * s.cos[i];
    // d/dx of E a cos(theta): the envelope's slope along the heading and the phase's k.
    gx += a * (s.slope[i] * c.dx[i] * s.cos[i] - e * c.kx[i] * s.sin[i]);
    gy += a * (s.slope[i] * c.dy[i] * s.cos[i] - e * c.ky[i] * s.sin[i]);
  }
  if (gradient) *gradient += Eigen::Vector3d(gx, gy, 0.0);
  return eta;
}

// The sums of one component's terms of addComponentKinematics's former form (docs/theory.md):
//   u = a w f_h cos(theta) along the heading d, w = a w f_v sin(theta);
//   du/dt = a w^2 f_h sin(theta) d - a w^2 f_v cos(theta) up; p = rho g a f_p cos(theta),
// with f_h = cosh(k (z + h)) / sinh(k h), f_v = sinh(k (z + h)) / sinh(k h), f_p = cosh(k (z +
// h)) / cosh(k h) from e = e^{kz} and r = e^{-2k(z+h)} = bed / e^2 (z <= 0: r <= 1, deep water
// cannot overflow; where e^2 underflows, bed = 0, k h > 350, and r = 0 / kTiny), each scaled by the envelope E (its rate E' keeps du/dt of E u). The
// gradients: d/dtheta times k cos b, k sin b, plus the envelope's slope along the heading; d/dz
// from d f_h / dz = k f_v, d f_v / dz = k f_h, d f_p / dz = k sinh / cosh.
void kinematicsSum(const ComponentTable& c, ComponentScratch& s, double z, bool gradients,
                   LinearKinematics& out) {
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; ++i) s.kz[i] = c.k[i] * z;
  exponentials(s.kz.data(), s.ekz.data(), n);
  double vx = 0, vy = 0, vz = 0, ax = 0, ay = 0, az = 0, p = 0;
  if (!gradients) {
#pragma omp simd reduction(+ : vx, vy, vz, ax, ay, az, p)
    for (std::size_t i = 0; i < n; ++i) {
      const double ekz = s.ekz[i], r = c.bed[i] / std::max(ekz * ekz, kTiny);
      const double cosh_ratio = ekz * (1.0 + r), sinh_ratio = ekz * (1.0 - r);
      const double f_h = cosh_ratio * c.over_sinh[i], f_v = sinh_ratio * c.over_sinh[i];
      const double co = s.cos[i], si = s.sin[i], e = s.value[i], rate = s.rate[i];
      const double vh = c.velocity[i] * f_h * co, vv = c.velocity[i] * f_v * si;
      const double ah = c.acceleration[i] * f_h * si, av = -c.acceleration[i] * f_v * co;
      vx += e * vh * c.dx[i];
      vy += e * vh * c.dy[i];
      vz += e * vv;
      ax += (e * ah + rate * vh) * c.dx[i];
      ay += (e * ah + rate * vh) * c.dy[i];
      az += e * av + rate * vv;
      p += e * c.pressure[i] * cosh_ratio * c.over_cosh[i] * co;
    }
    out = LinearKinematics();
    out.velocity = {vx, vy, vz};
    out.acceleration = {ax, ay, az};
    out.dynamic_pressure = p;
    return;
  }
  // With the gradients: every sum is a component's term times 1, d_x, d_y or a product of two
  // (k_x = k d_x, k_y = k d_y), so a first pass writes each component's fifteen terms and a
  // second takes the 26 sums as dot products (one pass of 26 reductions spills its registers).
  double* const t = s.terms.data();
  double *H1 = t, *H2 = t + n, *V1 = t + 2 * n, *V2 = t + 3 * n, *P1 = t + 4 * n;
  double *G1 = t + 5 * n, *G2 = t + 6 * n, *G3 = t + 7 * n, *G4 = t + 8 * n, *G5 = t + 9 * n;
  double *Z1 = t + 10 * n, *Z2 = t + 11 * n, *Z3 = t + 12 * n, *Z4 = t + 13 * n, *Z5 = t + 14 * n;
  const double *ekz_ = s.ekz.data(), *cos_ = s.cos.data(), *sin_ = s.sin.data();
  const double *value = s.value.data(), *rate_ = s.rate.data(), *slope_ = s.slope.data();
  const double *rate_slope = s.rate_slope.data(), *k_ = c.k.data(), *bed = c.bed.data();
  const double *over_sinh = c.over_sinh.data(), *over_cosh = c.over_cosh.data();
  const double *velocity = c.velocity.data(), *acceleration = c.acceleration.data();
  const double* pressure = c.pressure.data();
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    const double ekz = ekz_[i], r = bed[i] / std::max(ekz * ekz, kTiny);
    const double cosh_ratio = ekz * (1.0 + r), sinh_ratio = ekz * (1.0 - r);
    const double f_h = cosh_ratio * over_sinh[i], f_v = sinh_ratio * over_sinh[i];
    const double f_p = cosh_ratio * over_cosh[i];
    const double co = cos_[i], si = sin_[i];
    const double e = value[i], rate = rate_[i], slope = slope_[i], rs = rate_slope[i];
    const double k = k_[i], U = velocity[i], A = acceleration[i], P = pressure[i];
    // v and a (horizontal along d, vertical) and p; their d/dtheta; their d/dz.
    const double vh = U * f_h * co, vv = U * f_v * si;
    const double ah = A * f_h * si, av = -A * f_v * co;
    const double pp = P * f_p * co;
    const double vh_t = -U * f_h * si, vv_t = U * f_v * co;
    const double ah_t = A * f_h * co, av_t = A * f_v * si;
    const double p_t = -P * f_p * si;
    const double vh_z = k * U * f_v * co, vv_z = k * U * f_h * si;
    const double ah_z = k * A * f_v * si, av_z = -k * A * f_h * co;
    H1[i] = e * vh;  // E u: horizontal, along d
    H2[i] = e * ah + rate * vh;
    V1[i] = e * vv;
    V2[i] = e * av + rate * vv;
    P1[i] = e * pp;
    // d/dx_j = d_j (slope (.) + E k (.)_theta), the acceleration's with rate_slope and E'.
    G1[i] = slope * vh + e * k * vh_t;
    G2[i] = slope * ah + e * k * ah_t + rs * vh + rate * k * vh_t;
    G3[i] = slope * vv + e * k * vv_t;
    G4[i] = slope * av + e * k * av_t + rs * vv + rate * k * vv_t;
    G5[i] = slope * pp + e * k * p_t;
    Z1[i] = e * vh_z;  // d/dz
    Z2[i] = e * vv_z;
    Z3[i] = e * ah_z + rate * vh_z;
    Z4[i] = e * av_z + rate * vv_z;
    Z5[i] = e * k * P * sinh_ratio * over_cosh[i] * co;
  }
  const double *dx = c.dx.data(), *dy = c.dy.data();
  const double *dxx = c.dxx.data(), *dxy = c.dxy.data(), *dyy = c.dyy.data();
  const auto dot = [n](const double* a, const double* b) {
    double sum = 0.0;
#pragma omp simd reduction(+ : sum)
    for (std::size_t i = 0; i < n; ++i) sum += a[i] * b[i];
    return sum;
  };
  const auto total = [n](const double* a) {
    double sum = 0.0;
#pragma omp simd reduction(+ : sum)
    for (std::size_t i = 0; i < n; ++i) sum += a[i];
    return sum;
  };
  out.velocity = {dot(H1, dx), dot(H1, dy), total(V1)};
  out.acceleration = {dot(H2, dx), dot(H2, dy), total(V2)};
  out.dynamic_pressure = total(P1);
  const double vxy = dot(G1, dxy), axy = dot(G2, dxy);
  out.velocity_xy << dot(G1, dxx), vxy, vxy, dot(G1, dyy), dot(G3, dx), dot(G3, dy);
  out.acceleration_xy << dot(G2, dxx), axy, axy, dot(G2, dyy), dot(G4, dx), dot(G4, dy);
  out.pressure_xy = {dot(G5, dx), dot(G5, dy)};
  out.velocity_z = {dot(Z1, dx), dot(Z1, dy), total(Z2)};
  out.acceleration_z = {dot(Z3, dx), dot(Z3, dy), total(Z4)};
  out.pressure_z = total(Z5);
}

}  // namespace flexmoor::hydro
