// Forced motion through the time-history paths: a mass on a spring driven (a) by a nodal force
// F0 sin(w t) and (b) by a support moving as U sin(w t), both from rest, against the closed-form
// undamped response. The trapezoidal rule is second order, so halving dt must cut the error by
// about four; the finer run must also be close in absolute terms.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "libstruct/element/spring_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/solve/newmark.hpp"

namespace flexmoor {
namespace {

constexpr double kMass = 2.0, kStiffness = 800.0;  // omega0 = 20 rad/s
const double kOmega0 = std::sqrt(kStiffness / kMass);
const double kOmega = 0.6 * kOmega0;  // forcing below resonance

enum class Drive { Force, Support };

// Node 0 (x = 0) is the support, node 1 (x = 1) the mass; the spring carries compression.
std::unique_ptr<model::Model> oscillator(Drive drive, double amplitude) {
  auto m = std::make_unique<model::Model>();
  const int base = m->addNode(Eigen::Vector3d(0, 0, 0));
  const int mass = m->addNode(Eigen::Vector3d(1, 0, 0));
  m->addElement(std::make_unique<element::SpringElement>(base, mass, kStiffness, -1.0,
                                                         material::Compression::Carry));
  m->addElement(std::make_unique<element::PointMassElement>(mass, kMass));
  const auto sine = std::make_shared<model::SineFunction>(0.0, 1.0, 2.0 * M_PI / kOmega, 0.0);
  for (int k = 1; k < 3; ++k) m->constrain(mass, k);
  for (int k = 0; k < 3; ++k)
    m->constrain(base, k, k == 0 && drive == Drive::Support ? amplitude : 0.0,
                 k == 0 && drive == Drive::Support ? sine : nullptr);
  if (drive == Drive::Force) m->addNodalLoad(mass, Eigen::Vector3d(amplitude, 0, 0), sine);
  m->numberEquations();
  return m;
}

// x'' + w0^2 x = q sin(w t), x(0) = x'(0) = 0:
// x = q / (w0^2 - w^2) (sin(w t) - (w / w0) sin(w0 t)).
double exactDisplacement(double q, double t) {
  return q / (kOmega0 * kOmega0 - kOmega * kOmega) *
         (std::sin(kOmega * t) - kOmega / kOmega0 * std::sin(kOmega0 * t));
}

// Largest error of the mass's displacement over three natural periods, relative to the largest
// exact displacement.
double maxRelativeError(Drive drive, double dt,
                        solve::NewtonFlavour flavour = solve::NewtonFlavour::Full) {
  const double amplitude = drive == Drive::Force ? 10.0 : 0.01;
  // Support motion u_b = U sin(w t) acts on the mass as the force k u_b.
  const double q = drive == Drive::Force ? amplitude / kMass : kOmega0 * kOmega0 * amplitude;
  const auto m = oscillator(drive, amplitude);
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  solve::DynamicOptions o;
  const double duration = 3.0 * 2.0 * M_PI / kOmega0;
  o.schedule = {{dt, static_cast<int>(std::lround(duration / dt))}};
  o.convergence.displacement_tolerance = 1e-12;
  o.flavour = flavour;
  double error = 0.0, peak = 0.0;
  solve::integrate(assembler, state, o, {}, [&](const model::State& s) {
    const double exact = exactDisplacement(q, s.time);
    error = std::max(error, std::abs(s.displacement(0, 1) - exact));
    peak = std::max(peak, std::abs(exact));
  });
  return error / peak;
}

void expectSecondOrder(Drive drive) {
  const double dt = 2.0 * M_PI / kOmega0 / 100.0;
  const double coarse = maxRelativeError(drive, dt);
  const double fine = maxRelativeError(drive, dt / 2.0);
  ::testing::Test::RecordProperty("error_dt_T_over_100", std::to_string(coarse));
  ::testing::Test::RecordProperty("error_dt_T_over_200", std::to_string(fine));
  EXPECT_LT(fine, 1e-3);
  EXPECT_NEAR(coarse / fine, 4.0, 0.4) << "coarse " << coarse << ", fine " << fine;
}

TEST(NewmarkForcing, SineNodalForceFollowsClosedFormAtSecondOrder) {
  expectSecondOrder(Drive::Force);
}

TEST(NewmarkForcing, SineSupportMotionFollowsClosedFormAtSecondOrder) {
  expectSecondOrder(Drive::Support);
}

// On a linear system one Newton solve is exact, so the self-corrective scheme (Eq. 4.20: one
// solve a step, no iterations) follows the same trajectory as iterated Newton.
TEST(NewmarkForcing, SelfCorrectiveStepsMatchNewtonOnALinearSystem) {
  const double dt = 2.0 * M_PI / kOmega0 / 100.0;
  const double newton = maxRelativeError(Drive::Support, dt);
  const double self_corrective =
      maxRelativeError(Drive::Support, dt, solve::NewtonFlavour::SelfCorrective);
  EXPECT_NEAR(self_corrective, newton, 1e-9);
}

}  // namespace
}  // namespace flexmoor
