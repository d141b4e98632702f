// Axial Kelvin-Voigt damping of lines (MoorDyn's BA; libstruct/element/axial_damping.hpp): the
// axial force N = N_elastic + BA d(lambda)/dt, d(lambda)/dt the rate of the engineering strain.
//  (a) the element's damping matrices against central differences of its viscous force, in u'
//      and in u, for 2-, 3- and 4-node curved elements;
//  (b) a point mass on one axial cable element with BA, a Kelvin-Voigt oscillator
//      m x'' + (BA / L) x' + (EA / L) x = 0, integrated by Newmark (gamma = 1/2, beta = 1/4: no
//      numerical damping): its logarithmic decrement against zeta = BA / (2 L sqrt(k m)) and its
//      history against the closed-form damped oscillation;
//  (c) MoorDyn's negative input -zeta read from a case, BA = zeta (L / N) sqrt(EA m) with N the
//      line's segment (node interval) count, against that formula;
//  (d) a straight line stretched at a constant rate, integrated in time: its axial force equals
//      the material's elastic force plus BA times the strain rate, and so does its support
//      reaction.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <utility>

#include "apps/case/case_reader.hpp"
#include "libstruct/element/axial_damping.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/newmark.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/dynamic_models.hpp"
#include "tests/support/oblique_dashpot.hpp"

namespace flexmoor::test {
namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

const double kPi = std::acos(-1.0);

element::CableSection dampedSection(
    double E, double area, double density, double BA,
    material::Compression compression = material::Compression::TensionOnly) {
  element::CableSection s;
  s.area = area;
  s.density = density;
  s.material = std::make_shared<material::LinearElasticCable>(E, compression);
  s.axial_damping = BA;
  return s;
}

// max |J - J_fd| / max |J_fd|.
double relativeError(const MatrixXd& J, const MatrixXd& fd) {
  return (J - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
}

// The element's damping matrices against central differences of its viscous force (steps
// 1e-6 m in u, 1e-3 m/s in u'): the relative errors of df/du and df/du'.
std::pair<double, double> dampingMatrixErrors(const element::Element& e, const model::NodalField& X,
                                              const model::State& state) {
  const int n = e.dofCount();
  VectorXd f, plus, minus;
  element::LoadMatrices J;
  e.dampingForce({X, state, 0}, f, &J);
  EXPECT_GT(f.norm(), 0.0);
  EXPECT_TRUE(J.mass.isZero(0.0));
  MatrixXd fd_u(n, n), fd_v(n, n);
  for (int j = 0; j < n; ++j) {
    const auto column = [&](model::NodalField model::State::*field, double h) -> VectorXd {
      model::State s = state;
      (s.*field)(j % 3, j / 3) += h;
      e.dampingForce({X, s, 0}, plus, nullptr);
      (s.*field)(j % 3, j / 3) -= 2.0 * h;
      e.dampingForce({X, s, 0}, minus, nullptr);
      return (plus - minus) / (2.0 * h);
    };
    fd_u.col(j) = column(&model::State::displacement, 1e-6);
    fd_v.col(j) = column(&model::State::velocity, 1e-3);
  }
  return {relativeError(J.stiffness, fd_u), relativeError(J.damping, fd_v)};
}

// (a) A curved element (nodes on x = s, y = 0.3 sin s, z = 0.1 s^2, s in [0, 2] m), stretched by
// about 1 % and moved by smooth arbitrary fields, BA = 2.5e4 N s. Reference: central differences
// of the element's viscous force, steps 1e-6 m in u, 1e-3 m/s in u' (the force is linear in u').
// Metric: max |J - J_fd| / max |J_fd| per matrix. Tolerances 1e-9 for u (measured 3.9e-11 to
// 1.5e-10: the steps' round-off, eps / h) and 1e-12 for u' (measured 1.7e-14 to 2.7e-14).
TEST(LineDamping, DampingMatricesMatchCentralDifferences) {
  for (int n : {2, 3, 4}) {
    model::NodalField X(3, n);
    for (int i = 0; i < n; ++i) {
      const double s = 2.0 * i / (n - 1);
      X.col(i) = Vector3d(s, 0.3 * std::sin(s), 0.1 * s * s);
    }
    std::vector<int> nodes(n);
    for (int i = 0; i < n; ++i) nodes[i] = i;
    const auto e = element::makeCableElement(nodes, dampedSection(2e9, 1e-3, 7850.0, 2.5e4));
    model::State state(n);
    for (int i = 0; i < n; ++i) {
      const double s = X(0, i);
      state.displacement.col(i) = 0.01 * X.col(i) + 0.002 * Vector3d(std::cos(s), s, -s * s);
      state.velocity.col(i) = Vector3d(0.4 - 0.3 * s, 0.25 * std::cos(4.0 * s), -0.1 + 0.5 * s);
    }
    const auto [error_u, error_v] = dampingMatrixErrors(*e, X, state);
    std::cout << n << " nodes: df/du error " << error_u << ", df/du' error " << error_v << "\n";
    EXPECT_LT(error_u, 1e-9) << n << " nodes";
    EXPECT_LT(error_v, 1e-12) << n << " nodes";
  }
}

// (a) The spring's dashpot, the same kernel with y,1 = y2 - y1: c = 3e3 N s/m, the ends apart
// by (1.2, 0.4, -0.3) m and moving apart obliquely. Reference, metric and tolerance as above
// (measured 2.7e-10 in u, 3.0e-14 in u').
TEST(LineDamping, DashpotMatricesMatchCentralDifferences) {
  const test::ObliqueDashpot d;
  const model::NodalField& X = d.X;
  const element::SpringElement& e = d.element;
  const model::State& state = d.state;
  const auto [error_u, error_v] = dampingMatrixErrors(e, X, state);
  std::cout << "dashpot: df/du error " << error_u << ", df/du' error " << error_v << "\n";
  EXPECT_LT(error_u, 1e-9);
  EXPECT_LT(error_v, 1e-12);
}

// A mass m on node 1 at x = L, held along x by one element from the fixed node 0: a cable
// element (EA = k L, BA = c L: force k x + c x' along the axis, up to the Green-strain law's
// nonlinearity) or a spring with a dashpot (k, c; exactly linear along its axis).
std::unique_ptr<model::Model> dampedOscillator(bool spring, double k, double m, double L,
                                               double c) {
  auto model = std::make_unique<model::Model>();
  model->addNode(Vector3d::Zero());
  model->addNode(Vector3d(L, 0.0, 0.0));
  if (spring)
    model->addElement(
        std::make_unique<element::SpringElement>(0, 1, k, -1.0, material::Compression::Carry, c));
  else
    model->addElement(element::makeCableElement(
        {0, 1}, dampedSection(k * L, 1.0, 0.0, c * L, material::Compression::Carry)));
  model->addElement(std::make_unique<element::PointMassElement>(1, m));
  for (int d = 0; d < 3; ++d) model->constrain(0, d);
  model->constrain(1, 1);
  model->constrain(1, 2);
  model->numberEquations();
  return model;
}

// (b) k = 1e5 N/m, m = 1000 kg (omega = 10 rad/s), zeta = 0.05, released from x0 = 1e-4 m at
// rest, dt = T / 400, 10 periods, two ways: a cable element (EA = 1e6 N, L = 10 m, BA = 2 zeta L
// sqrt(k m); strain 1e-5, so the Green-strain law's nonlinearity, 1.5 x0 / L, is 1.5e-5) and a
// spring with a dashpot (c = 2 zeta sqrt(k m); exactly linear along its axis). References: the
// velocity vanishes at t = k pi / omega_d, where |x| = x0 exp(-zeta omega t), so the decrement
// over the run gives zeta exactly; and x(t) = x0 exp(-zeta omega t) (cos omega_d t + zeta /
// sqrt(1 - zeta^2) sin omega_d t). The trapezoidal rule has no numerical damping; its phase error
// (omega dt)^2 / 12 per radian times the decaying amplitude peaks at 1 / (zeta omega):
// 2.06e-5 * 20 / e = 1.5e-4 x0. Tolerances: zeta to 5e-5 relative (measured 3.7e-5 cable,
// 3.5e-5 spring), the history to 2e-4 x0 (measured 1.51e-4 both, the phase error above).
TEST(LineDamping, KelvinVoigtOscillatorDecaysAtItsDampingRatio) {
  const double EA = 1e6, L = 10.0, m = 1000.0, zeta = 0.05, x0 = 1e-4;
  const double k = EA / L, omega = std::sqrt(k / m);
  const double c = 2.0 * zeta * std::sqrt(k * m);
  for (const bool spring : {false, true}) {
    const auto model_ptr = dampedOscillator(spring, k, m, L, c);
    const model::Model& model = *model_ptr;
    const model::Assembler assembler(model);
    ASSERT_TRUE(assembler.hasDamping());
    model::State state = model.initialState();
    state.displacement(0, 1) = x0;
    const double period = 2.0 * kPi / omega;
    solve::DynamicOptions options;
    options.schedule = {{period / 400.0, 4000}};
    options.load_factor = 1.0;
    options.convergence.residual_tolerance = 1e-10;  // one solve is exact (see below)
    std::vector<double> t{0.0}, x{x0}, v{0.0};
    const solve::DynamicReport report =
        solve::integrate(assembler, state, options, {}, [&](const model::State& s) {
          t.push_back(s.time);
          x.push_back(s.displacement(0, 1));
          v.push_back(s.velocity(0, 1));
        });

    const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
    double history_error = 0.0;
    for (size_t i = 0; i < t.size(); ++i) {
      const double exact = x0 * std::exp(-zeta * omega * t[i]) *
                           (std::cos(omega_d * t[i]) +
                            zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(omega_d * t[i]));
      history_error = std::max(history_error, std::abs(x[i] - exact) / x0);
    }
    // |x| at the velocity's zero crossings (linear interpolation: the error, O(omega^2 x dt^2),
    // is 2e-4 of the ratio's own change per sample, negligible). The first is the release.
    const std::vector<double> crossings = zeroCrossings(t, v);
    ASSERT_GE(crossings.size(), 20u);
    ASSERT_EQ(crossings.front(), 0.0);
    const auto x_at = [&](double time) {
      const size_t i = std::upper_bound(t.begin(), t.end(), time) - t.begin();
      const double f = (time - t[i - 1]) / (t[i] - t[i - 1]);
      return std::abs(x[i - 1] + f * (x[i] - x[i - 1]));
    };
    const int half_cycles = static_cast<int>(crossings.size()) - 1;
    const double decrement = 2.0 * std::log(x0 / x_at(crossings.back())) / half_cycles;
    const double measured_zeta = decrement / std::sqrt(4.0 * kPi * kPi + decrement * decrement);
    std::cout << (spring ? "spring and dashpot" : "cable with BA") << ": zeta " << measured_zeta
              << " (closed form " << zeta << ", relative error " << measured_zeta / zeta - 1.0
              << "), history error " << history_error << " x0, "
              << static_cast<double>(report.iterations) / report.steps
              << " Newton iterations per step, " << report.cuts << " cuts\n";
    EXPECT_NEAR(measured_zeta / zeta, 1.0, 5e-5);
    EXPECT_LT(history_error, 2e-4);
    // A linear system: with C_d in the effective tangent the first solve is exact and the second
    // confirms it (Eq. 5.1 needs a small increment), 2 per step (measured 2.000 both).
    // Without it each solve leaves c gamma / (beta h) / (a0 m) = zeta omega dt = 8e-3 of the
    // error (measured with C_d taken out of the tangent: 4.0 per step).
    EXPECT_LT(static_cast<double>(report.iterations) / report.steps, 2.05);
  }
}

// The dashpot oscillator of (b) (omega = 10 rad/s, zeta = 0.05, dt = T / 40, 20 periods) with
// plain Newmark and with HHT alpha = -0.1, whose residual takes the viscous force at both ends
// of the step, (1 + alpha) F_d,n+1 - alpha F_d,n. Reference: the scheme's exact recurrence on
// x'' + 2 zeta omega x' + omega^2 x = 0 (Hilber, Hughes & Taylor 1977; dynamic_models.hpp),
// from the consistent start (x0, 0, -omega^2 x0). Metric: max |x - x_n| / x0. Tolerance 1e-10
// (round-off; measured 1.7e-11 Newmark, 9.9e-12 HHT).
TEST(LineDamping, DashpotRunFollowsTheSchemesDampedRecurrence) {
  const double k = 1e5, m = 1000.0, zeta = 0.05, x0 = 1e-4, omega = std::sqrt(k / m);
  const double c = 2.0 * zeta * std::sqrt(k * m), dt = 2.0 * kPi / omega / 40.0;
  for (const double alpha : {0.0, -0.1}) {
    const auto model = dampedOscillator(true, k, m, 10.0, c);
    const model::Assembler assembler(*model);
    model::State state = model->initialState();
    state.displacement(0, 1) = x0;
    solve::DynamicOptions options;
    options.schedule = {{dt, 800}};
    options.load_factor = 1.0;
    options.hht_alpha = alpha;
    // One solve is exact; 1e-12 would sit below the round-off of k (l - L) at l = 10 m (2e-11
    // of k x0) once the motion has decayed, and steps would be cut.
    options.convergence.residual_tolerance = 1e-10;
    const Eigen::Matrix3d A =
        amplificationMatrix(schemeConstants(options), omega * dt, 2.0 * zeta * omega * dt);
    Eigen::Vector3d s(x0, 0.0, -omega * omega * dt * dt * x0);
    double worst = 0.0;
    const solve::DynamicReport report =
        solve::integrate(assembler, state, options, {}, [&](const model::State& st) {
          s = A * s;
          worst = std::max(worst, std::abs(st.displacement(0, 1) - s(0)) / x0);
        });
    std::cout << "alpha " << alpha << ": worst |x - x_n| / x0 " << worst << "\n";
    ASSERT_EQ(report.cuts, 0) << "the recurrence is for steps of dt";
    EXPECT_LT(worst, 1e-10) << "alpha " << alpha;
  }
}

// (c) MoorDyn (Line.cpp, a negative BA input): BA = zeta * UnstrLen / N * sqrt(EA * w), N its
// segment count, w its mass per length. A 100 m line of E A = 1e11 Pa * 1e-4 m^2 = 1e7 N, w =
// 7850 kg/m^3 * 1e-4 m^2, zeta = 0.8, as 20 linear elements and as 10 quadratic ones (20 node
// intervals either way): every element's viscous force at a uniform strain rate r (velocity r x
// along the unstretched line) is BA r at its ends. Reference: the formula above, by hand.
// Tolerance 1e-12 relative (measured 1.3e-15 and 1.8e-15).
TEST(LineDamping, MoorDynNegativeZetaIsConvertedPerSegment) {
  const double zeta = 0.8, length = 100.0, EA = 1e11 * 1e-4, w = 7850.0 * 1e-4, segments = 20;
  const double moordyn_BA = zeta * length / segments * std::sqrt(EA * w);
  for (const char* mesh : {"elements: 20, order: 2", "elements: 10, order: 3"}) {
    const std::string text = std::string(R"(units: SI
materials:
  steel: {type: linear_elastic, E: 1.0e11 Pa}
sections:
  wire: {material: steel, area: 1.0e-4 m^2, density: 7850 kg/m^3, damping: {zeta: 0.8}}
lines:
  - {name: cable, from: [0, 0, 0], to: [100 m, 0, 0], )") +
                             mesh + R"(, section: wire}
supports:
  - {node: cable.start, fix: [x, y, z]}
  - {node: cable.end, fix: [x, y, z]}
steps:
  - static: {name: s}
)";
    const app::Case c = app::readCase(writeCase("moordyn-zeta.yaml", text));
    const model::Model& m = *c.model;
    model::State s = m.initialState();
    const double rate = 0.01;  // 1/s
    for (int n = 0; n < m.nodeCount(); ++n) s.velocity(0, n) = rate * m.reference()(0, n);
    double worst = 0.0;
    VectorXd f;
    for (int e = 0; e < m.elementCount(); ++e) {
      ASSERT_TRUE(m.element(e).hasDamping());
      m.element(e).dampingForce({m.reference(), s, e}, f, nullptr);
      const double end_force = f.tail<3>().norm();
      worst = std::max(worst, std::abs(end_force / (moordyn_BA * rate) - 1.0));
    }
    std::cout << mesh << ": BA " << moordyn_BA << " N s, worst relative error " << worst << "\n";
    EXPECT_LT(worst, 1e-12) << mesh;
  }
  EXPECT_DOUBLE_EQ(element::dampingCoefficientOfRatio(zeta, length / segments, EA, w), moordyn_BA);
}

// A spring's dashpot read from a case (`damping: 50 N*s/m`, in kN*s/m to exercise the units):
// its force at a relative speed of 0.3 m/s along the spring is c v = 15 N. Reference: by hand.
// Tolerance 1e-12 relative (measured 0).
TEST(LineDamping, SpringDashpotIsReadFromTheCase) {
  const app::Case c = app::readCase(writeCase("dashpot.yaml", R"(units: SI
nodes:
  1: [0, 0, 0]
  2: [1, 0, 0]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 100 N/m, damping: 0.05 kN*s/m}
  - {type: point_mass, node: 2, mass: 1 kg}
supports:
  - {node: 1, fix: [x, y, z]}
  - {node: 2, fix: [y, z]}
steps:
  - static: {name: s}
)"));
  const model::Model& m = *c.model;
  ASSERT_TRUE(m.element(0).hasDamping());
  model::State s = m.initialState();
  s.velocity(0, 1) = 0.3;
  VectorXd f;
  m.element(0).dampingForce({m.reference(), s, 0}, f, nullptr);
  EXPECT_NEAR(f(3) / 15.0, 1.0, 1e-12);
  EXPECT_NEAR(f(0) / -15.0, 1.0, 1e-12);
}

// (d) A straight 10 m line of two elements (2 or 3 nodes each), E A = 2e11 Pa * 1e-4 m^2, BA =
// 3e5 N s, its end pulled along the line at r = 0.05 m/s from an initial stretch of 0.2 % (the
// interior nodes free along the line, with the consistent uniform velocity), 200 steps of 0.01 s.
// Reference: the uniform stretch is the exact motion (no acceleration anywhere), so at every
// step the axial force is N = E A (lambda^2 - 1) lambda / 2 (Eq. 2.53, N = S lambda A0) +
// BA r / L, lambda = 1 + u_end / L, at the integration points, at the element ends and as the
// anchor's reaction. Tolerance 1e-11 of N (measured 1.6e-13 linear, 9.3e-13 quadratic).
TEST(LineDamping, StretchedAtAConstantRateCarriesElasticPlusViscousForce) {
  const double E = 2e11, A = 1e-4, L = 10.0, BA = 3e5, rate = 0.05, u0 = 0.002 * L;
  for (int n : {2, 3}) {
    model::Model model;
    const int node_count = 2 * (n - 1) + 1;
    for (int i = 0; i < node_count; ++i)
      model.addNode(Vector3d(L * i / (node_count - 1), 0.0, 0.0));
    for (int e = 0; e < 2; ++e) {
      std::vector<int> nodes;
      for (int i = 0; i < n; ++i) nodes.push_back(e * (n - 1) + i);
      model.addElement(element::makeCableElement(nodes, dampedSection(E, A, 7850.0, BA)));
    }
    // u_end(t) = u0 + rate t: a ramp started at t = -u0 / rate, over a long time.
    const double duration = 1000.0;
    const auto ramp = std::make_shared<model::RampFunction>(-u0 / rate, duration);
    for (int c = 0; c < 3; ++c) model.constrain(0, c);
    model.constrain(node_count - 1, 0, rate * duration, ramp);
    for (int i = 1; i < node_count; ++i) {
      model.constrain(i, 1);
      model.constrain(i, 2);
    }
    model.numberEquations();
    const model::Assembler assembler(model);
    model::State state = model.initialState();
    for (int i = 0; i < node_count; ++i) {
      const double x = model.reference()(0, i) / L;
      state.displacement(0, i) = u0 * x;
      state.velocity(0, i) = rate * x;
    }
    solve::DynamicOptions options;
    options.schedule = {{0.01, 200}};
    options.load_factor = 1.0;
    double worst = 0.0;
    solve::integrate(assembler, state, options, {}, [&](const model::State& s) {
      const double lambda = 1.0 + s.displacement(0, node_count - 1) / L;
      const double expected =
          0.5 * E * A * (lambda * lambda - 1.0) * lambda + BA * s.velocity(0, node_count - 1) / L;
      for (const element::ElementResult& r : assembler.elementResults(s)) {
        for (double N : r.point_tension) worst = std::max(worst, std::abs(N / expected - 1.0));
        for (double N : r.end_tension) worst = std::max(worst, std::abs(N / expected - 1.0));
      }
      const double reaction = -assembler.reactions(s)(0, 0);
      worst = std::max(worst, std::abs(reaction / expected - 1.0));
    });
    std::cout << n << " nodes: worst relative error of N " << worst << " after t = " << state.time
              << " s\n";
    EXPECT_NEAR(state.time, 2.0, 1e-9);
    EXPECT_LT(worst, 1e-11) << n << " nodes";
  }
}

}  // namespace
}  // namespace flexmoor::test
