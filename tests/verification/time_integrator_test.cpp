// The steppable time integrator (libstruct/solve/time_integrator.hpp):
//  - a support driven between steps with drive() moves the structure exactly as the same motion
//    given as a history does;
//  - save() and restore() repeat a stretch of steps to the bit;
//  - motion-dependent node loads (load_point.hpp) in the effective tangent: a mass with a node
//    load of stiffness k_L, damping c_L and added mass m_L moves exactly as the structural
//    oscillator of stiffness k + k_L, mass m + m_L and damping c_L, and with the load matrices
//    in the tangent Newton solves once per step of this linear problem (without them, with an
//    added mass above the structure's own, it diverges).
#include "libstruct/solve/time_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "libstruct/element/spring_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/solve/newmark.hpp"

namespace flexmoor {
namespace {

constexpr double kMass = 2.0, kStiffness = 800.0;   // omega0 = 20 rad/s
constexpr double kAmplitude = 0.01, kOmega = 12.0;  // support motion U sin(w t)

// Node 0 (x = 0) is the support, node 1 (x = 1) the mass on a massless spring; y and z fixed.
// With `history`, the support's x follows U sin(w t); without, it is held at 0 (to be driven).
std::unique_ptr<model::Model> oscillator(bool history) {
  auto m = std::make_unique<model::Model>();
  const int base = m->addNode(Eigen::Vector3d(0, 0, 0));
  const int mass = m->addNode(Eigen::Vector3d(1, 0, 0));
  m->addElement(std::make_unique<element::SpringElement>(base, mass, kStiffness, -1.0,
                                                         material::Compression::Carry));
  m->addElement(std::make_unique<element::PointMassElement>(mass, kMass));
  const auto sine = std::make_shared<model::SineFunction>(0.0, 1.0, 2.0 * M_PI / kOmega, 0.0);
  for (int k = 1; k < 3; ++k) m->constrain(mass, k);
  for (int k = 0; k < 3; ++k)
    m->constrain(base, k, k == 0 && history ? kAmplitude : 0.0, k == 0 && history ? sine : nullptr);
  m->numberEquations();
  return m;
}

// The spring is massless, so the support's acceleration (exact for the history, a difference
// quotient for drive()) acts on nothing: the two runs agree to round-off. Reference: the history
// run; tolerance 1e-12 of the amplitude.
TEST(TimeIntegrator, DrivenSupportMatchesTheSameMotionAsAHistory) {
  const auto with_history = oscillator(true), driven = oscillator(false);
  const model::Assembler a_history(*with_history), a_driven(*driven);
  solve::DynamicOptions o;
  o.load_factor = 1.0;
  const double dt = 0.002;
  model::State s_history = with_history->initialState(), s_driven = driven->initialState();
  solve::TimeIntegrator i_history(a_history, o), i_driven(a_driven, o);
  i_history.start(s_history);
  i_driven.start(s_driven);
  double worst = 0.0;
  for (int n = 1; n <= 500; ++n) {
    const double t = n * dt;
    i_history.step(s_history, dt);
    i_driven.drive(0, 0, kAmplitude * std::sin(kOmega * t),
                   kAmplitude * kOmega * std::cos(kOmega * t));
    i_driven.step(s_driven, dt);
    worst = std::max(worst, std::abs(s_driven.displacement(0, 1) - s_history.displacement(0, 1)));
  }
  EXPECT_LT(worst, 1e-12 * kAmplitude);
  EXPECT_GT(std::abs(s_driven.displacement(0, 1)), 1e-3 * kAmplitude);  // it moved
}

// A dof that no support holds cannot be driven.
TEST(TimeIntegrator, DrivingAFreeDofIsRefused) {
  const auto m = oscillator(false);
  const model::Assembler a(*m);
  solve::DynamicOptions o;
  solve::TimeIntegrator integrator(a, o);
  EXPECT_THROW(integrator.drive(1, 0, 0.0, 0.0), std::invalid_argument);
}

// Twenty steps after restore() repeat the twenty after save() exactly (reference: the first
// pass; tolerance 0, bit for bit), with modified Newton so the schedule's memory matters.
TEST(TimeIntegrator, RestoreRepeatsTheStepsToTheBit) {
  const auto m = oscillator(true);
  const model::Assembler a(*m);
  solve::DynamicOptions o;
  o.load_factor = 1.0;
  o.flavour = solve::NewtonFlavour::Modified;
  o.stiffness_update = 3;
  solve::TimeIntegrator integrator(a, o);
  model::State s = m->initialState();
  integrator.start(s);
  for (int n = 0; n < 7; ++n) integrator.step(s, 0.003);
  const solve::IntegratorCheckpoint saved = integrator.save(s);
  for (int n = 0; n < 20; ++n) integrator.step(s, 0.003);
  const model::State first = s;
  integrator.restore(saved, s);
  for (int n = 0; n < 20; ++n) integrator.step(s, 0.003);
  EXPECT_EQ(s.time, first.time);
  EXPECT_EQ((s.displacement - first.displacement).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((s.velocity - first.velocity).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((s.acceleration - first.acceleration).cwiseAbs().maxCoeff(), 0.0);
}

// A linear node load on the mass: f = -k_L u - c_L u' - m_L u'' along x.
class LinearNodeLoad final : public model::NodeLoad {
 public:
  LinearNodeLoad(int node, double k, double c, double m) : node_(node), k_(k), c_(c), m_(m) {}
  int node() const override { return node_; }
  model::PointForce evaluate(const model::LoadPoint& p, bool) const override {
    model::PointForce f;
    const Eigen::Matrix3d x = Eigen::Vector3d::UnitX().asDiagonal();
    const Eigen::Vector3d u = p.position - Eigen::Vector3d(1, 0, 0);
    f.force = -x * (k_ * u + c_ * p.velocity + m_ * p.acceleration);
    f.d_position = -k_ * x;
    f.d_velocity = -c_ * x;
    f.d_acceleration = -m_ * x;
    return f;
  }

 private:
  int node_;
  double k_, c_, m_;
};

constexpr double kLoadStiffness = 400.0, kLoadDamping = 6.0, kAddedMass = 3.0;

std::unique_ptr<model::Model> loadedOscillator(bool as_load) {
  auto m = std::make_unique<model::Model>();
  const int base = m->addNode(Eigen::Vector3d(0, 0, 0));
  const int mass = m->addNode(Eigen::Vector3d(1, 0, 0));
  const double k = as_load ? kStiffness : kStiffness + kLoadStiffness;
  m->addElement(
      std::make_unique<element::SpringElement>(base, mass, k, -1.0, material::Compression::Carry));
  m->addElement(
      std::make_unique<element::PointMassElement>(mass, as_load ? kMass : kMass + kAddedMass));
  for (int k = 0; k < 3; ++k) m->constrain(base, k);
  for (int k = 1; k < 3; ++k) m->constrain(mass, k);
  m->addNodalLoad(mass, Eigen::Vector3d(50.0, 0, 0));  // a step load at t = 0
  if (as_load)
    m->addNodeLoad(
        std::make_shared<LinearNodeLoad>(mass, kLoadStiffness, kLoadDamping, kAddedMass));
  m->numberEquations();
  return m;
}

struct LoadedRun {
  double x = 0.0;
  solve::DynamicReport report;
};

LoadedRun runLoaded(bool as_load, solve::DynamicOptions::LoadMatrixUpdate update) {
  const auto m = loadedOscillator(as_load);
  const model::Assembler a(*m);
  solve::DynamicOptions o;
  o.load_factor = 1.0;
  o.schedule = {{0.01, 100}};  // omega dt = 0.35
  o.load_matrices = update;
  o.convergence.residual_tolerance = 1e-10;
  o.convergence.displacement_tolerance = 1e-10;
  // The structural twin's damping c_L as Rayleigh mass damping: C = (c_L / (m + m_L)) M.
  if (!as_load) o.rayleigh_mass = kLoadDamping / (kMass + kAddedMass);
  model::State s = m->initialState();
  LoadedRun r;
  r.report = solve::integrate(a, s, o);
  r.x = s.displacement(0, 1);
  return r;
}

// Reference: the structural twin; tolerance 1e-10 of the static deflection 50 / 1200 (Newton's
// convergence tolerance is 1e-10).
TEST(TimeIntegrator, NodeLoadMatricesEnterTheEffectiveTangent) {
  using Update = solve::DynamicOptions::LoadMatrixUpdate;
  const LoadedRun twin = runLoaded(false, Update::Step);
  const LoadedRun loaded = runLoaded(true, Update::Step);
  const double scale = 50.0 / (kStiffness + kLoadStiffness);
  EXPECT_NEAR(loaded.x, twin.x, 1e-10 * scale);
  // A linear problem with its exact tangent: one solve a step, and a second whose increment
  // shows the displacement test that it has converged.
  EXPECT_EQ(loaded.report.steps, 100);
  EXPECT_EQ(loaded.report.iterations, 200);
  EXPECT_EQ(loaded.report.cuts, 0);
  // Without the load matrices each Newton iteration multiplies the error by -m_L / m = -1.5: it
  // diverges however small the step (the light line's trouble the matrices are there for).
  EXPECT_THROW(runLoaded(true, Update::Off), solve::ConvergenceError);
}

}  // namespace
}  // namespace flexmoor
