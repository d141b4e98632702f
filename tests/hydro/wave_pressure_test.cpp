// The incident wave pressure on membranes (docs/theory.md#wave-pressure-on-membranes; Eq. 3.30-3.37
// with a pressure field p(y, t)): the elements' surface-load stiffness against central
// differences of their nodal forces, the resultant on fixed submerged strips against the closed
// integral of the linear wave pressure, and what the gradient part of the load stiffness is
// worth to Newton.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include "libhydro/loads/wave_pressure_load.hpp"
#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/material/membrane_material.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/shape/quad_shape.hpp"
#include "libstruct/shape/triangle_shape.hpp"
#include "libstruct/solve/solve_log.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/ocean_models.hpp"
#include "tests/support/surface_load_check.hpp"

namespace flexmoor::test {
namespace {

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::Vector3d;
using Eigen::VectorXd;

// A smooth pressure field with a gradient in every direction and its analytic gradient.
class QuadraticPressure final : public model::SurfaceLoad {
 public:
  model::PointPressure evaluate(const model::LoadPoint& p, bool) const override {
    const Vector3d& y = p.position;
    return {3.0 + 0.7 * y.x() - 1.1 * y.z() + 0.4 * y.x() * y.y(),
            Vector3d(0.7 + 0.4 * y.y(), 0.4 * y.x(), -1.1)};
  }
};

template <class Shape, int N>
double curvedElementError(const std::string& shape, const model::SurfaceLoad& load,
                          const Vector3d& offset) {
  std::vector<int> nodes(N);
  for (int i = 0; i < N; ++i) nodes[i] = i;
  const auto e = element::makeMembraneElement(
      shape, nodes, {0.01, 2.0, std::make_shared<material::MooneyRivlinMembrane>(2300.0, 280.0)});
  model::NodalField X(3, N);
  model::State s(N);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int i = 0; i < N; ++i) {
    const Vector2d p = Shape::node(i);
    X.col(i) = offset + Vector3d(2.0 * p.x() + 0.1 * p.y(), 1.5 * p.y(),
                                 0.3 * p.x() * p.x() + 0.1 * p.y() * p.y());
    s.displacement.col(i) << 0.3 * X(0, i) + noise(rng), 0.2 * X(1, i) + noise(rng),
        0.1 * X(0, i) + noise(rng);
  }
  return surfaceStiffnessError(*e, X, s, load);
}

std::shared_ptr<hydro::Sea> linearWaveSea(double depth) {
  auto sea = stillWater(depth);
  sea->addComponent(
      hydro::WaveComponent::fromHeightAndPeriod(2.0, 6.0, 0.0, 0.3, depth, kStandardGravity));
  // Linear theory below the mean level, unstretched: what the closed forms integrate.
  sea->setSurfaceKinematics(hydro::SurfaceKinematics::ConstantAboveMean);
  return sea;
}

// Reference: central differences of the nodal forces, step 1e-6; tolerance 1e-8 relative to the
// largest entry (measured 3.7e-10 to 6.9e-10 for the analytic field, up to 1.1e-9 for the wave
// pressure 6 m down, whose gradient is itself a central difference of step 1e-4 / k).
TEST(WavePressure, SurfaceLoadStiffnessMatchesFiniteDifference) {
  const QuadraticPressure field;
  const hydro::IncidentPressureLoad wave(linearWaveSea(30.0), hydro::WaterSide::Positive);
  const Vector3d submerged(4.0, -1.0, -6.0);
  for (const model::SurfaceLoad* load : {static_cast<const model::SurfaceLoad*>(&field),
                                         static_cast<const model::SurfaceLoad*>(&wave)}) {
    const double q4 = curvedElementError<shape::QuadShape<4>, 4>("quad", *load, submerged);
    const double q8 = curvedElementError<shape::QuadShape<8>, 8>("quad", *load, submerged);
    const double t6 = curvedElementError<shape::TriangleShape<6>, 6>("triangle", *load, submerged);
    const double t3 = curvedElementError<shape::TriangleShape<3>, 3>("triangle", *load, submerged);
    std::cout << "surface load stiffness error: Q4 " << q4 << ", Q8 " << q8 << ", T6 " << t6
              << ", T3 " << t3 << "\n";
    EXPECT_LT(q4, 1e-8);
    EXPECT_LT(q8, 1e-8);
    EXPECT_LT(t6, 1e-8);
    EXPECT_LT(t3, 1e-8);
  }
}

// The axisymmetric meridian per radian (field evaluated on the meridian); same reference and
// tolerance (measured 2.1e-10 to 2.9e-10).
TEST(WavePressure, AxisymmetricSurfaceLoadStiffnessMatchesFiniteDifference) {
  const QuadraticPressure field;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  for (int n : {2, 3, 4}) {
    std::vector<int> nodes(n);
    for (int i = 0; i < n; ++i) nodes[i] = i;
    const auto e = element::makeAxisymmetricMembrane(
        nodes, {0.01, 1.0, std::make_shared<material::MooneyRivlinMembrane>(2300.0, 280.0)});
    model::NodalField X(3, n);
    model::State s(n);
    for (int i = 0; i < n; ++i) {
      const double t = double(i) / (n - 1);
      X.col(i) << 2.0 + t + 0.2 * t * t, 0.0, 3.0 * t;
      s.displacement.col(i) << 0.5 + noise(rng), 0.0, noise(rng);
    }
    const double error = surfaceStiffnessError(*e, X, s, field);
    std::cout << "axisymmetric " << n << "-node: " << error << "\n";
    EXPECT_LT(error, 1e-8) << n;
  }
}

// The pressure at single points under a crest (t = 0 at x = -phase / k: eta = a = 1 m), water on
// the positive side: -p. Below the mean level the linear pressure; between the mean level and
// the crest, constant extrapolation of the dynamic part gives rho g (eta - z), zero at the
// surface; above it zero, with a zero gradient. Reference: those closed forms; tolerance 1e-12
// relative to rho g a (exact arithmetic of the same terms).
TEST(WavePressure, PressureIsZeroAboveTheSurfaceAndHydrostaticBelowTheCrest) {
  const double rho = kSeaWaterDensity, g = kStandardGravity, h = 30.0;
  const auto sea = linearWaveSea(h);
  const hydro::WaveComponent& w = sea->components()[0];
  const hydro::IncidentPressureLoad load(sea, hydro::WaterSide::Positive);
  model::LoadPoint p;
  const double x = -w.phase / w.k, scale = rho * g * w.amplitude;
  const auto at = [&](double z) {
    p.position = Vector3d(x, 2.0, z);
    return load.evaluate(p, true);
  };
  EXPECT_NEAR(at(0.4).pressure, -rho * g * (w.amplitude - 0.4), 1e-12 * scale);
  EXPECT_NEAR(at(-3.0).pressure,
              -(rho * g * 3.0 + scale * std::cosh(w.k * (h - 3.0)) / std::cosh(w.k * h)),
              1e-12 * scale);
  const model::PointPressure dry = at(1.2);
  EXPECT_EQ(dry.pressure, 0.0);
  EXPECT_EQ(dry.d_position.norm(), 0.0);
}

// A structured mesh of Q8 elements on the map `at` of the unit square (s, t in [0, 1]), nx by
// ny, nodes shared; returns the element indices.
std::vector<int> q8Grid(model::Model& m, int nx, int ny,
                        const std::function<Vector3d(double, double)>& at) {
  std::vector<std::vector<int>> id(2 * nx + 1, std::vector<int>(2 * ny + 1, -1));
  for (int a = 0; a <= 2 * nx; ++a)
    for (int b = 0; b <= 2 * ny; ++b)
      if (a % 2 == 0 || b % 2 == 0) id[a][b] = m.addNode(at(a / (2.0 * nx), b / (2.0 * ny)));
  const auto section = element::MembraneSection{
      0.001, 1000.0, std::make_shared<material::LinearElasticPlaneStress>(1.0e8, 0.3)};
  std::vector<int> elements;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = 2 * i, b = 2 * j;
      elements.push_back(m.addElement(element::makeMembraneElement(
          "quad",
          {id[a][b], id[a + 2][b], id[a + 2][b + 2], id[a][b + 2], id[a + 1][b], id[a + 2][b + 1],
           id[a + 1][b + 2], id[a][b + 1]},
          section)));
    }
  return elements;
}

Vector3d stripResultant(const std::function<Vector3d(double, double)>& at, hydro::WaterSide side,
                        const std::shared_ptr<const hydro::Sea>& sea, double t) {
  model::Model m;
  const std::vector<int> elements = q8Grid(m, 8, 2, at);
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k) m.constrain(n, k);
  m.addSurfaceLoad(std::make_shared<hydro::IncidentPressureLoad>(sea, side), elements);
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State s = m.initialState();
  s.time = t;
  s.load_factor = 1.0;
  return totalExternalLoad(assembler, s);
}

// A fixed horizontal strip x in [0, Lx], y in [0, Ly] at z = -d (8 x 2 Q8s, normal +z), water
// above it (its positive side): the resultant is -e_z int p dA, with (theta = k x - omega t + phi)
//   int p dA = Ly [rho g d Lx + rho g a cosh(k (h - d)) / cosh(k h) (sin theta(Lx) - sin theta(0))
//   / k],
// the hydrostatic part plus the linear wave's. A vertical strip at x = x0, y in [0, Ly],
// z in [-z1, -z0] (normal +x), water on its negative side: +e_x int p dA with
//   int p dA = Ly [rho g (z1^2 - z0^2) / 2 + rho g a cos theta(x0) (sinh(k (h - z0)) -
//   sinh(k (h - z1))) / (k cosh(k h))].
// At 4 times of the 6 s wave (H = 2 m, h = 30 m, k = 0.112 /m) on Lx = 20 m, Ly = 4 m at d = 5 m
// and on z in [-9 m, -1 m] at x0 = 7 m; tolerance 2e-9 of the hydrostatic part (measured up to
// 2.2e-11 on the horizontal strip and 4.6e-10 on the vertical one: the 3 x 3 Gauss rule on
// elements of k dx = 0.28 and of 4 m across the cosh), the components across the strip's normal
// below 1e-9 of it (they cancel to round-off).
TEST(WavePressure, ResultantOnSubmergedStripsMatchesClosedForm) {
  const double h = 30.0, rho = kSeaWaterDensity, g = kStandardGravity;
  const auto sea = linearWaveSea(h);
  const hydro::WaveComponent& w = sea->components()[0];
  const double a = w.amplitude, k = w.k;
  const double Lx = 20.0, Ly = 4.0, d = 5.0, x0 = 7.0, z0 = 1.0, z1 = 9.0;
  const auto theta = [&](double x, double t) { return k * x - w.omega * t + w.phase; };
  for (const double t : {0.0, 1.3, 2.9, 4.4}) {
    const Vector3d horizontal =
        stripResultant([&](double s, double r) { return Vector3d(Lx * s, Ly * r, -d); },
                       hydro::WaterSide::Positive, sea, t);
    const double hydrostatic = rho * g * d * Lx * Ly;
    const double expected_h =
        hydrostatic + Ly * rho * g * a * std::cosh(k * (h - d)) / std::cosh(k * h) *
                          (std::sin(theta(Lx, t)) - std::sin(theta(0.0, t))) / k;
    EXPECT_NEAR(-horizontal.z(), expected_h, 2e-9 * hydrostatic) << t;
    EXPECT_LT(horizontal.head<2>().norm(), 1e-9 * hydrostatic) << t;

    const Vector3d vertical = stripResultant(
        [&](double s, double r) { return Vector3d(x0, Ly * s, -z1 + (z1 - z0) * r); },
        hydro::WaterSide::Negative, sea, t);
    const double hydrostatic_v = rho * g * (z1 * z1 - z0 * z0) / 2.0 * Ly;
    const double expected_v =
        hydrostatic_v + Ly * rho * g * a * std::cos(theta(x0, t)) *
                            (std::sinh(k * (h - z0)) - std::sinh(k * (h - z1))) /
                            (k * std::cosh(k * h));
    EXPECT_NEAR(vertical.x(), expected_v, 2e-9 * hydrostatic_v) << t;
    EXPECT_LT(vertical.tail<2>().norm(), 1e-9 * hydrostatic_v) << t;
    std::cout << "t " << t << ": horizontal strip " << -horizontal.z() << " N (closed form "
              << expected_h << ", relative " << (-horizontal.z() - expected_h) / hydrostatic
              << "), vertical strip " << vertical.x() << " N (closed form " << expected_v
              << ", relative " << (vertical.x() - expected_v) / hydrostatic_v << ")\n";
  }
}

// The wave pressure with its gradient left out of the load stiffness (the constant-pressure
// part stays): what Newton would have without the gradient part.
class WithoutGradient final : public model::SurfaceLoad {
 public:
  explicit WithoutGradient(std::shared_ptr<const model::SurfaceLoad> load)
      : load_(std::move(load)) {}
  model::PointPressure evaluate(const model::LoadPoint& p, bool jacobians) const override {
    return {load_->evaluate(p, jacobians).pressure, Vector3d::Zero()};
  }

 private:
  std::shared_ptr<const model::SurfaceLoad> load_;
};

// A 2 m square membrane (4 x 4 Q8s, E h0 = 1e5 N/m, nu 0.3) stretched 3% by its edges, 0.1 m
// down with water below it (its negative side): the hydrostatic pressure pushes it up and
// falls by rho g per metre it rises, a spring of rho g per unit area that is as stiff as the
// membrane's lowest mode (about 2 rho g for the 4300 N/m of tension). Full Newton from the flat
// state in two increments of the load factor (tolerances 1e-10 on the displacement and the
// residual); the second starts near its equilibrium, where the rate shows: with the gradient
// part of the load stiffness it converges quadratically (measured 5 iterations; asserted <= 6),
// without it linearly, with about the ratio rho g / k of that mode (measured 29; asserted >= 20).
// Both reach the same equilibrium (the centre rises 45 mm).
struct NewtonRun {
  int iterations;   // in the second increment
  double centre_z;  // the centre node's height at equilibrium
};

NewtonRun newtonRun(bool gradient) {
  model::Model m;
  const double L = 2.0, stretch = 0.03;
  const std::vector<int> elements =
      q8Grid(m, 4, 4, [&](double s, double t) { return Vector3d(L * s, L * t, -0.1); });
  const auto hold = std::make_shared<model::RampFunction>(-2.0, 1.0);  // 1 from t = -1 on
  for (int n = 0; n < m.nodeCount(); ++n) {
    const Vector3d X = m.reference().col(n);
    const bool edge = std::abs(X.x()) < 1e-12 || std::abs(X.x() - L) < 1e-12 ||
                      std::abs(X.y()) < 1e-12 || std::abs(X.y() - L) < 1e-12;
    if (!edge) continue;
    m.constrain(n, 0, stretch * (X.x() - L / 2.0), hold);
    m.constrain(n, 1, stretch * (X.y() - L / 2.0), hold);
    m.constrain(n, 2, 0.0, hold);
  }
  std::shared_ptr<const model::SurfaceLoad> load =
      std::make_shared<hydro::IncidentPressureLoad>(stillWater(30.0), hydro::WaterSide::Negative);
  if (!gradient) load = std::make_shared<WithoutGradient>(load);
  m.addSurfaceLoad(load, elements);
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State s = m.initialState();
  solve::StaticOptions o;
  o.max_iterations = 100;
  o.increments = 2;
  o.convergence.displacement_tolerance = 1e-10;
  o.convergence.residual_tolerance = 1e-10;
  const solve::StaticReport r = solve::solveStatic(assembler, s, o);
  const int centre = m.nodeCount() / 2;  // (L / 2, L / 2): the grid's nodes go column by column
  const double centre_z = m.reference()(2, centre) + s.displacement(2, centre);
  std::cout << (gradient ? "with" : "without")
            << " the gradient part: " << r.increments.front().iterations << " then "
            << r.increments.back().iterations << " iterations, centre node at z = " << centre_z
            << "\n";
  return {r.increments.back().iterations, centre_z};
}

TEST(WavePressure, GradientStiffnessMakesNewtonQuadratic) {
  const NewtonRun with = newtonRun(true), without = newtonRun(false);
  EXPECT_LE(with.iterations, 6);
  EXPECT_GE(without.iterations, 20);
  EXPECT_NEAR(with.centre_z, without.centre_z, 1e-9);  // the same equilibrium, to the tolerance
  EXPECT_GT(with.centre_z, -0.1 + 0.04);               // lifted (measured 45 mm)
}

}  // namespace
}  // namespace flexmoor::test
