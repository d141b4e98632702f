// The held kinematics of a time step (libhydro/waves/held_kinematics.hpp): the first query at a
// point is Sea::at itself (to the bit); a query 1-3 cm away at the same time is the Taylor
// expansion of the held flow with its closed-form gradient, within the remainder bound
// |dx|^2 sum a omega k^2 of the exact flow (deep water, below the mean level, constant
// extrapolation: each component's velocity has second derivatives at most a omega k^2 along any
// direction, so the remainder is at most |dx|^2 / 2 of that per component of the vector; the
// bound is twice it); a new time, another key, a point beyond the radius or across the surface
// is evaluated afresh.
#include "libhydro/waves/held_kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libhydro/waves/wave_synthesis.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kG = 9.80665;

std::shared_ptr<Sea> deepSea(double& bound_per_dx2) {
  const double inf = std::numeric_limits<double>::infinity();
  auto sea = std::make_shared<Sea>(Water{1025.0, inf, kG});
  SynthesisOptions o;
  o.components = 60;
  o.seed = 4;
  bound_per_dx2 = 0.0;
  for (const WaveComponent& c :
       synthesise(WaveSpectrum::jonswap(4.0, 9.0, 3.3), o, inf, kG).components) {
    sea->addComponent(c);
    bound_per_dx2 += c.amplitude * c.omega * c.k * c.k;
  }
  sea->setSurfaceKinematics(SurfaceKinematics::ConstantAboveMean);
  return sea;
}

TEST(HeldKinematics, FirstQueryExactNearbyOnesTaylorExpanded) {
  double bound = 0.0;
  const auto sea = deepSea(bound);
  const HeldKinematics held(sea, 0.5);
  const Eigen::Vector3d x(12.0, -3.0, -6.0);
  const double t = 31.7;
  FluidGradient g, g_exact;
  const FluidPoint first = held.at(7, x, t, g), exact = sea->at(x, t, g_exact);
  EXPECT_EQ(first.velocity, exact.velocity);
  EXPECT_EQ(first.acceleration, exact.acceleration);
  EXPECT_EQ(first.pressure, exact.pressure);
  EXPECT_EQ(g.velocity, g_exact.velocity);
  for (const Eigen::Vector3d& dx :
       {Eigen::Vector3d(0.01, 0.0, 0.0), Eigen::Vector3d(0.0, 0.02, -0.01),
        Eigen::Vector3d(-0.02, 0.01, 0.02)}) {
    FluidGradient gh, ge;
    const FluidPoint h = held.at(7, x + dx, t, gh), e = sea->at(x + dx, t, ge);
    EXPECT_EQ(gh.velocity, g_exact.velocity);  // the held gradient
    EXPECT_NEAR((h.velocity - (exact.velocity + g_exact.velocity * dx)).norm(), 0.0,
                1e-15 * exact.velocity.norm());  // the expansion itself
    EXPECT_LT((h.velocity - e.velocity).norm(), bound * dx.squaredNorm()) << dx.transpose();
    EXPECT_GT((h.velocity - e.velocity).norm(), 0.0);  // an approximation, not the exact flow
  }
  EXPECT_EQ(held.counts().evaluations, 1);
  EXPECT_EQ(held.counts().reuses, 3);
}

TEST(HeldKinematics, NewTimeKeyDistanceOrSideEvaluatesAfresh) {
  double bound = 0.0;
  const auto sea = deepSea(bound);
  const HeldKinematics held(sea, 0.5);
  const Eigen::Vector3d x(0.0, 0.0, -2.0);
  FluidGradient g, ge;
  held.at(1, x, 5.0, g);
  const auto exactAt = [&](const Eigen::Vector3d& p, double t) { return sea->at(p, t, ge); };
  // Another time: the held flow is forgotten.
  EXPECT_EQ(held.at(1, x, 5.1, g).velocity, exactAt(x, 5.1).velocity);
  // Another key, or beyond the radius: a fresh evaluation.
  EXPECT_EQ(held.at(2, x, 5.1, g).velocity, exactAt(x, 5.1).velocity);
  const Eigen::Vector3d far = x + Eigen::Vector3d(0.6, 0.0, 0.0);
  EXPECT_EQ(held.at(1, far, 5.1, g).velocity, exactAt(far, 5.1).velocity);
  EXPECT_EQ(held.counts().evaluations, 4);
  // Above the local surface from a wet held point: evaluated afresh, dry.
  const double eta = sea->elevation(x, 5.1);
  const Eigen::Vector3d above(x.x(), x.y(), eta + 0.05), below(x.x(), x.y(), eta - 0.05);
  held.at(3, below, 5.1, g);
  const FluidPoint dry = held.at(3, above, 5.1, g);
  EXPECT_FALSE(dry.wet);
  EXPECT_EQ(held.counts().evaluations, 6);
}

}  // namespace
}  // namespace flexmoor::hydro
