// Verification of the Newmark / HHT-alpha time integration (Eq. 4.55-4.63, solve/newmark.cpp)
// against exact linear theory, and of its energy behaviour on a nonlinear swinging cable.
//
// References (all independent of the integrator's output):
//  - the trapezoidal rule (gamma = 1/2, beta = 1/4) on x'' + omega^2 x = 0 conserves
//    m v^2 / 2 + k x^2 / 2 exactly and, released from x0 at rest with the consistent initial
//    acceleration, gives x_n = x0 cos(n theta) with tan(theta / 2) = omega dt / 2 (the scheme is
//    time-symmetric, so no sine term): T_num / T = (omega dt / 2) / atan(omega dt / 2);
//  - for a linear multi-dof system, each mode follows the scheme's own scalar recurrence
//    s_{n+1} = A(omega dt, 2 zeta omega dt) s_n, s = (q, dt q', dt^2 q'') (Hilber, Hughes & Taylor
//    1977; tests/support/dynamic_models.cpp), so the exact discrete response is the modal
//    superposition of A^n s_0 with the closed-form modes of the spring chain;
//  - viscous damping C = a_M M on an oscillator gives the damping ratio zeta = a_M / (2 omega);
//  - a taut string's transverse frequencies for consistent-mass linear elements (closed form in
//    tests/support/dynamic_models.hpp);
//  - conservation of the total energy of an undamped, conservative structure.
#include "libstruct/solve/newmark.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/modal.hpp"
#include "tests/support/dynamic_models.hpp"

namespace flexmoor::test {
namespace {

const double kPi = std::acos(-1.0);

// Every accepted state of a run, the initial one first.
struct History {
  std::vector<double> t;
  std::vector<model::NodalField> u, v;
};

History integrateAndRecord(const model::Assembler& assembler, model::State state,
                           const solve::DynamicOptions& options) {
  History h;
  const auto record = [&h](const model::State& s) {
    h.t.push_back(s.time);
    h.u.push_back(s.displacement);
    h.v.push_back(s.velocity);
  };
  record(state);
  solve::integrate(assembler, state, options, {}, record);
  return h;
}

// For linear systems: the tangent once (modified Newton that never refreshes it: exact for a
// linear system) and convergence on the residual alone. A step is accepted only after at least
// one solve, and one solve is exact for a linear system, so the tolerance (1e-9 of the largest
// force; round-off in the inertia term, a0 (u - u_n) - ..., sits near 1e-11 at small dt) does not
// limit the accuracy.
solve::DynamicOptions linearRun(double dt, int steps) {
  solve::DynamicOptions o;
  o.schedule = {{dt, steps}};
  o.flavour = solve::NewtonFlavour::Modified;
  o.stiffness_update = 1 << 30;
  o.convergence.use_displacement = false;
  o.convergence.residual_tolerance = 1e-9;
  return o;
}

// Peaks of a sampled signal (local maxima above zero), each refined by the parabola through the
// three samples around it.
std::vector<double> positivePeaks(const std::vector<double>& x) {
  std::vector<double> peaks;
  for (size_t k = 1; k + 1 < x.size(); ++k)
    if (x[k] > 0.0 && x[k] >= x[k - 1] && x[k] > x[k + 1]) {
      const double curvature = x[k + 1] - 2.0 * x[k] + x[k - 1];
      peaks.push_back(x[k] - 0.125 * (x[k + 1] - x[k - 1]) * (x[k + 1] - x[k - 1]) / curvature);
    }
  return peaks;
}

// ---------------------------------------------------------------------------------------------
// Single dof: a point mass m on a spring k along x (other end fixed), released from x0 at rest.
// Reference: x_n = x0 cos(n theta), tan(theta / 2) = omega dt / 2 (trapezoidal rule, exact).
// Tolerances: trajectory and amplitude sqrt(x^2 + m v^2 / k) = x0 to 1e-9 relative (round-off
// over thousands of steps); the period from zero crossings (linear interpolation, least-squares
// fit over 400 cycles) to 1e-6 relative: one crossing's interpolation error is below
// (omega dt)^2 dt / 60 and changes sign with the sampling phase, so the fit's error is far
// smaller; the period elongation itself is 4e-3 (dt / T = 1/20) and 7e-4 (1/50).
void expectTrapezoidalOscillator(int steps_per_period) {
  const double m = 2.0, k = 50.0, x0 = 0.01;
  const double omega = std::sqrt(k / m), period = 2.0 * kPi / omega;
  const double dt = period / steps_per_period, omega_dt = omega * dt;
  const int cycles = 400;
  const SpringChain chain = makeSpringChain({m}, {k});
  const int node = chain.masses[0];
  const model::Assembler assembler(*chain.model);
  model::State state = chain.model->initialState();
  state.displacement(0, node) = x0;
  const History h = integrateAndRecord(assembler, state, linearRun(dt, cycles * steps_per_period));

  const double theta = 2.0 * std::atan(0.5 * omega_dt);
  double trajectory_error = 0.0, amplitude_error = 0.0;
  std::vector<double> x;
  for (size_t n = 0; n < h.t.size(); ++n) {
    const double xn = h.u[n](0, node), vn = h.v[n](0, node);
    x.push_back(xn);
    trajectory_error = std::max(trajectory_error, std::abs(xn - x0 * std::cos(n * theta)) / x0);
    amplitude_error =
        std::max(amplitude_error, std::abs(std::sqrt(xn * xn + m * vn * vn / k) / x0 - 1.0));
  }
  const double measured = periodFromCrossings(zeroCrossings(h.t, x)) / period;
  const double expected = trapezoidalPeriodRatio(omega_dt);
  std::cout << std::setprecision(10) << "[ Newmark SDOF, dt/T = 1/" << steps_per_period
            << " ] T_num/T measured " << measured << ", exact " << expected << " (rel. diff "
            << std::abs(measured / expected - 1.0) << "); amplitude error " << amplitude_error
            << ", trajectory error " << trajectory_error << "\n";
  EXPECT_EQ(static_cast<int>(h.t.size()), cycles * steps_per_period + 1);
  EXPECT_LT(trajectory_error, 1e-9);
  EXPECT_LT(amplitude_error, 1e-9);
  EXPECT_NEAR(measured / expected, 1.0, 1e-6);
}

TEST(Newmark, SingleDofPeriodErrorIsTrapezoidalRuleAtTwentyStepsPerPeriod) {
  expectTrapezoidalOscillator(20);
}

TEST(Newmark, SingleDofPeriodErrorIsTrapezoidalRuleAtFiftyStepsPerPeriod) {
  expectTrapezoidalOscillator(50);
}

// ---------------------------------------------------------------------------------------------
// Two equal masses m between three springs k, K, k (walls at both ends). Closed-form modes:
//   phi_1 = (1, 1) / sqrt(2 m), omega_1^2 = k / m;   phi_2 = (1, -1) / sqrt(2 m),
//   omega_2^2 = (k + 2 K) / m.
struct TwoMassChain {
  double m = 1.0, k = 1.0, K = 4.0;
  double omega(int i) const { return std::sqrt((i == 0 ? k : k + 2.0 * K) / m); }
  Eigen::Vector2d shape(int i) const {
    return Eigen::Vector2d(1.0, i == 0 ? 1.0 : -1.0) / std::sqrt(2.0 * m);
  }
};

struct ModalComparison {
  double displacement_error = 0.0;  // max over steps, relative to the largest initial displacement
  double velocity_error = 0.0;      // relative to omega_max * that displacement
  std::vector<std::vector<double>> q;  // measured modal coordinates phi_i^T M x, per mode
};

// Runs the chain from x0 at rest and compares every step with the modal superposition of the
// scheme's exact recurrence (damping_ratio: Rayleigh mass damping a_M = 2 zeta_i omega_i, i.e.
// zeta_i = a_M / (2 omega_i)).
ModalComparison compareWithModalRecurrence(const TwoMassChain& c, const Eigen::Vector2d& x0,
                                           const solve::DynamicOptions& options,
                                           History* history = nullptr) {
  const SpringChain chain = makeSpringChain({c.m, c.m}, {c.k, c.K, c.k});
  const model::Assembler assembler(*chain.model);
  model::State state = chain.model->initialState();
  for (int i = 0; i < 2; ++i) state.displacement(0, chain.masses[i]) = x0(i);
  const History h = integrateAndRecord(assembler, state, options);
  const double dt = options.schedule.front().dt;
  const SchemeConstants scheme = schemeConstants(options);

  ModalComparison r;
  r.q.resize(2);
  const double scale = x0.cwiseAbs().maxCoeff();
  std::vector<Eigen::Matrix3d> A;
  std::vector<Eigen::Vector3d> s;
  for (int i = 0; i < 2; ++i) {
    const double W = c.omega(i) * dt;
    A.push_back(amplificationMatrix(scheme, W, options.rayleigh_mass * dt));
    const double q0 = c.shape(i).dot(c.m * x0);
    s.emplace_back(q0, 0.0, -W * W * q0);  // consistent start at rest: q'' = -omega^2 q
  }
  for (size_t n = 0; n < h.t.size(); ++n) {
    Eigen::Vector2d x_exact = Eigen::Vector2d::Zero(), v_exact = Eigen::Vector2d::Zero();
    for (int i = 0; i < 2; ++i) {
      x_exact += s[i](0) * c.shape(i);
      v_exact += (s[i](1) / dt) * c.shape(i);
      s[i] = A[i] * s[i];
    }
    const Eigen::Vector2d x(h.u[n](0, chain.masses[0]), h.u[n](0, chain.masses[1]));
    const Eigen::Vector2d v(h.v[n](0, chain.masses[0]), h.v[n](0, chain.masses[1]));
    r.displacement_error =
        std::max(r.displacement_error, (x - x_exact).cwiseAbs().maxCoeff() / scale);
    r.velocity_error =
        std::max(r.velocity_error, (v - v_exact).cwiseAbs().maxCoeff() / (c.omega(1) * scale));
    for (int i = 0; i < 2; ++i) r.q[i].push_back(c.shape(i).dot(c.m * x));
  }
  if (history) *history = h;
  return r;
}

// Reference: the modal superposition of the trapezoidal recurrence; tolerance 1e-9 (round-off).
// Each mode's period, from the zero crossings of its modal coordinate over 100 cycles of mode 1,
// against T_i (omega_i dt / 2) / atan(omega_i dt / 2): 1e-6 relative (as for the single dof).
TEST(Newmark, TwoMassChainFollowsModalRecurrence) {
  const TwoMassChain c;
  const double dt = 2.0 * kPi / c.omega(0) / 40.0;
  const int steps = 100 * 40;
  History h;
  const ModalComparison r =
      compareWithModalRecurrence(c, Eigen::Vector2d(0.02, -0.005), linearRun(dt, steps), &h);
  std::cout << "[ Newmark two masses ] max deviation from the modal recurrence: displacement "
            << r.displacement_error << ", velocity " << r.velocity_error << "\n";
  EXPECT_LT(r.displacement_error, 1e-9);
  EXPECT_LT(r.velocity_error, 1e-9);
  for (int i = 0; i < 2; ++i) {
    const double period = 2.0 * kPi / c.omega(i);
    const double measured = periodFromCrossings(zeroCrossings(h.t, r.q[i])) / period;
    const double expected = trapezoidalPeriodRatio(c.omega(i) * dt);
    std::cout << std::setprecision(10) << "[ Newmark two masses ] mode " << i + 1
              << ": T_num/T measured " << measured << ", exact " << expected << "\n";
    EXPECT_NEAR(measured / expected, 1.0, 1e-6) << "mode " << i + 1;
  }
}

// HHT-alpha, alpha = -0.1 (gamma = 0.6, beta = 0.3025), on the two-mass chain with
// omega_2 = 100 omega_1 and dt = T_1 / 200 (omega_1 dt = 0.031, omega_2 dt = 3.14), both modes
// excited equally, over 10 cycles of mode 1 (2000 steps).
// References: the modal HHT recurrence (tolerance 1e-9); its spectral radius rho(omega dt).
// Theory: rho(omega_1 dt)^2000 = 1 - 2e-5, rho(omega_2 dt) ~ 0.91 per step.
// Checks: the low mode keeps its amplitude to 1e-3 over the 10 cycles (largest |q_1| over the last
// cycle, parabolic peak: sampling error < (omega_1 dt)^2 / 8 = 1.2e-4); the high mode is gone
// (< 1e-9 of its start); its decay over 100 steps, from the envelope (largest |q_2| in windows of
// 20 steps, several of its periods), agrees with rho(omega_2 dt)^100 within 5% (the envelope of
// a damped pair sampled at 20-step windows is only that precise; the recurrence check above is
// the exact one).
TEST(Newmark, HhtAlphaDampsHighModeAndKeepsLowMode) {
  TwoMassChain c;
  const double omega_2 = 100.0;
  c.K = 0.5 * (omega_2 * omega_2 * c.m - c.k);
  const double dt = 2.0 * kPi / c.omega(0) / 200.0;
  solve::DynamicOptions o = linearRun(dt, 2000);
  o.hht_alpha = -0.1;
  const double q0 = 0.01;
  const Eigen::Vector2d x0 = q0 * (c.shape(0) + c.shape(1));  // modal coordinates q_1 = q_2 = q0
  const ModalComparison r = compareWithModalRecurrence(c, x0, o);
  EXPECT_LT(r.displacement_error, 1e-9);
  EXPECT_LT(r.velocity_error, 1e-9);

  const SchemeConstants scheme = schemeConstants(o);
  EXPECT_DOUBLE_EQ(scheme.gamma, 0.6);
  EXPECT_DOUBLE_EQ(scheme.beta, 0.3025);
  const double rho_1 = spectralRadius(amplificationMatrix(scheme, c.omega(0) * dt));
  const double rho_2 = spectralRadius(amplificationMatrix(scheme, c.omega(1) * dt));
  const auto window_max = [](const std::vector<double>& q, size_t from, size_t count) {
    double m = 0.0;
    for (size_t k = from; k < from + count && k < q.size(); ++k) m = std::max(m, std::abs(q[k]));
    return m;
  };
  const double q1_start = r.q[0].front(), q2_start = r.q[1].front();
  // The last cycle and a half: after a whole number of cycles the peak sits on the last sample.
  const std::vector<double> last_peaks =
      positivePeaks(std::vector<double>(r.q[0].end() - 301, r.q[0].end()));
  ASSERT_FALSE(last_peaks.empty());
  const double low_kept = *std::max_element(last_peaks.begin(), last_peaks.end()) / q1_start;
  const double high_left = window_max(r.q[1], r.q[1].size() - 200, 200) / q2_start;
  const double decay_100 = window_max(r.q[1], 120, 20) / window_max(r.q[1], 20, 20);
  std::cout << "[ HHT alpha = -0.1 ] rho(w1 dt) = " << rho_1
            << " (10 cycles: " << std::pow(rho_1, 2000) << "), rho(w2 dt) = " << rho_2
            << "; low mode kept " << low_kept << ", high mode left " << high_left
            << ", high-mode decay over 100 steps " << decay_100
            << " (rho^100 = " << std::pow(rho_2, 100) << ")\n";
  EXPECT_GT(std::pow(rho_1, 2000), 1.0 - 1e-3);
  EXPECT_LT(rho_2, 0.95);
  EXPECT_GT(low_kept, 1.0 - 1e-3);
  EXPECT_LT(low_kept, 1.0 + 1e-9);
  EXPECT_LT(high_left, 1e-9);
  EXPECT_NEAR(decay_100 / std::pow(rho_2, 100), 1.0, 0.05);
}

// Rayleigh mass damping C = a_M M on the single dof (omega = 2 pi, T = 1), a_M = 2 zeta omega with
// zeta = 0.02, dt = T / 200, 10 cycles. Reference: zeta = a_M / (2 omega); measured by the
// logarithmic decrement of the positive peaks (parabolic refinement) over the 10 cycles,
// delta = ln(x_0 / x_N) / N, zeta = delta / sqrt(4 pi^2 + delta^2). Tolerance 1% (the scheme's
// error in the damping ratio is O((omega dt)^2) ~ 1e-3 relative). The run must also match the
// damped modal recurrence to 1e-9.
TEST(Newmark, RayleighMassDampingGivesDampingRatio) {
  const double m = 1.0, omega = 2.0 * kPi, k = m * omega * omega, zeta = 0.02;
  const double dt = 1.0 / 200.0;
  solve::DynamicOptions o = linearRun(dt, 10 * 200 + 20);
  o.rayleigh_mass = 2.0 * zeta * omega;
  const SpringChain chain = makeSpringChain({m}, {k});
  const int node = chain.masses[0];
  const model::Assembler assembler(*chain.model);
  model::State state = chain.model->initialState();
  const double x0 = 0.01;
  state.displacement(0, node) = x0;
  const History h = integrateAndRecord(assembler, state, o);

  std::vector<double> x;
  double recurrence_error = 0.0;
  const Eigen::Matrix3d A =
      amplificationMatrix(schemeConstants(o), omega * dt, o.rayleigh_mass * dt);
  Eigen::Vector3d s(x0, 0.0, -omega * omega * dt * dt * x0);
  for (size_t n = 0; n < h.t.size(); ++n) {
    x.push_back(h.u[n](0, node));
    recurrence_error = std::max(recurrence_error, std::abs(x.back() - s(0)) / x0);
    s = A * s;
  }
  // The first peak is the release point itself (x0 at t = 0); the later ones are the refined
  // maxima, one per damped period.
  std::vector<double> peaks{x0};
  for (double p : positivePeaks(x)) peaks.push_back(p);
  const int cycles = 10;
  ASSERT_GT(static_cast<int>(peaks.size()), cycles);
  const double delta = std::log(peaks[0] / peaks[cycles]) / cycles;
  const double measured = delta / std::sqrt(4.0 * kPi * kPi + delta * delta);
  std::cout << "[ Rayleigh mass damping ] zeta measured " << measured << ", expected " << zeta
            << " (rel. diff " << measured / zeta - 1.0 << "); recurrence error " << recurrence_error
            << "\n";
  EXPECT_LT(recurrence_error, 1e-9);
  EXPECT_NEAR(measured / zeta, 1.0, 0.01);
}

// ---------------------------------------------------------------------------------------------
// A taut cable (12 L2 elements, 3-D, uniform stretch 1.001 from a prescribed end displacement)
// released from a small multiple of its mode k (amplitude 1e-5 L: the nonlinear frequency shift,
// of order (EA / T)(k pi a / L)^2 / 8, is below 1e-6). The modal coordinate q = phi^T M (u - u_0)
// is measured by its zero crossings over 50 cycles at dt = T_k / 40.
// Reference: 2 pi / omega_k with omega_k from the string closed form for consistent-mass linear
// elements, times the trapezoidal period error (omega_k dt / 2) / atan(omega_k dt / 2)
// (= 1.00206 here). Tolerance 1e-4 relative.
void expectTautCableModePeriod(int k) {
  TautCableInputs in;
  const TautCable cable = makeTautCable(in);
  const model::Assembler assembler(*cable.model);
  const model::State pretensioned = pretension(cable, assembler);
  solve::ModalOptions mo;
  mo.modes = assembler.equationCount();
  const solve::ModalResult modes = solve::naturalModes(assembler, pretensioned, mo);
  const std::vector<int> transverse = modesAlong(modes, {1, 2});
  ASSERT_GE(static_cast<int>(transverse.size()), 2 * k);
  const int mode = transverse[2 * (k - 1)];  // y and z modes come in equal pairs
  const double omega =
      linearStringFrequency(in.elements, k, in.tension(), in.massPerLength(), in.stretchedLength());
  EXPECT_NEAR(modes.omega[mode] / omega, 1.0, 1e-8);

  const model::NodalField& shape = modes.shapes[mode];
  const double amplitude = 1e-5 * in.length;
  model::State state = pretensioned;
  state.displacement += (amplitude / shape.cwiseAbs().maxCoeff()) * shape;
  const double period = 2.0 * kPi / omega, dt = period / 40.0;
  solve::DynamicOptions o;
  o.schedule = {{dt, 50 * 40}};
  o.convergence.use_displacement = false;
  o.convergence.residual_tolerance = 1e-10;
  const History h = integrateAndRecord(assembler, state, o);

  model::SparseMatrix M;
  assembler.mass(pretensioned, element::MassKind::Consistent, M);
  const Eigen::VectorXd phi = assembler.restrictToFree(solve::asVector(shape));
  const Eigen::VectorXd u0 = assembler.restrictToFree(solve::asVector(pretensioned.displacement));
  std::vector<double> q;
  for (const model::NodalField& u : h.u)
    q.push_back(phi.dot(M * (assembler.restrictToFree(solve::asVector(u)) - u0)));
  const double measured = periodFromCrossings(zeroCrossings(h.t, q));
  const double expected = period * trapezoidalPeriodRatio(omega * dt);
  std::cout << std::setprecision(10) << "[ Taut cable, mode " << k << " ] period measured "
            << measured << " s, expected " << expected << " s (2 pi / omega_k = " << period
            << ", rel. diff " << measured / expected - 1.0 << ")\n";
  EXPECT_NEAR(measured / expected, 1.0, 1e-4);
}

TEST(Newmark, TautCableReleasedFromFirstModeKeepsItsPeriod) { expectTautCableModePeriod(1); }

TEST(Newmark, TautCableReleasedFromThirdModeKeepsItsPeriod) { expectTautCableModePeriod(3); }

// ---------------------------------------------------------------------------------------------
// Energy of a swinging cable: 8 L3 elements, pinned at both ends (span 8, unstretched length 10,
// EA = 2e4, rho A = 1, g = 10), hanging in equilibrium, released at rest from the equilibrium plus
// its first out-of-plane (swinging) mode (largest displacement `amplitude`),
// undamped, 100 periods of the first mode with dt = T_1 / 40.
// Reference: conservation of E = v^T M v / 2 + strain energy + gravity potential (the potential
// evaluated in tests/support with the element's Gauss points, E gamma^2 / 2 on the Green strain).
// The trapezoidal rule conserves energy exactly only for linear systems; for a nonlinear one its
// energy error stays bounded at moderate amplitude but can grow without bound at large amplitude
// (Simo & Tarnow 1992): measured here, amplitude 0.3 gains 4000 times the vibration energy within
// 8 periods. HHT-alpha removes that: its energy can only decay.
struct SwingResult {
  double vibration_energy = 0.0;  // E(0) - E(equilibrium)
  double largest_gain = 0.0;      // max over steps of E(t) - E(0)
  double largest_error = 0.0;     // max over steps of |E(t) - E(0)|
};

SwingResult swingCable(double amplitude, double hht_alpha, int steps_per_period = 40) {
  const SaggingCable cable = makeSaggingCable(SaggingCableInputs{});
  const model::Assembler assembler(*cable.model);
  const model::State hanging = hangSaggingCable(cable, assembler);
  solve::ModalOptions mo;
  mo.modes = 6;
  const solve::ModalResult modes = solve::naturalModes(assembler, hanging, mo);
  const std::vector<int> out_of_plane = modesAlong(modes, {1});
  EXPECT_EQ(out_of_plane.front(), 0);  // the swinging mode is the lowest
  const double T1 = 2.0 * kPi / modes.omega[0];

  model::State state = hanging;
  const model::NodalField& shape = modes.shapes[out_of_plane.front()];
  state.displacement += (amplitude / shape.cwiseAbs().maxCoeff()) * shape;
  model::SparseMatrix M;
  assembler.mass(hanging, element::MassKind::Consistent, M);
  const auto energy = [&](const model::State& s) {
    const Eigen::VectorXd v = assembler.restrictToFree(solve::asVector(s.velocity));
    return 0.5 * v.dot(M * v) + cablePotential(cable, s).total();
  };
  const double E0 = energy(state);
  SwingResult r;
  r.vibration_energy = E0 - cablePotential(cable, hanging).total();
  solve::DynamicOptions o;
  o.schedule = {{T1 / steps_per_period, 100 * steps_per_period}};
  o.hht_alpha = hht_alpha;
  o.convergence.use_displacement = false;
  o.convergence.residual_tolerance = 1e-10;
  const solve::DynamicReport report =
      solve::integrate(assembler, state, o, {}, [&](const model::State& s) {
        const double dE = energy(s) - E0;
        r.largest_gain = std::max(r.largest_gain, dE);
        r.largest_error = std::max(r.largest_error, std::abs(dE));
      });
  std::cout << "[ Swinging cable, amplitude " << amplitude << ", alpha " << hht_alpha
            << ", dt = T1 / " << steps_per_period << " ] T1 = " << T1 << " s, vibration energy "
            << r.vibration_energy << ", largest energy error "
            << r.largest_error / r.vibration_energy << " of it, largest gain "
            << r.largest_gain / r.vibration_energy << "; " << report.steps << " steps, "
            << report.iterations << " iterations, " << report.cuts << " cuts\n";
  EXPECT_GT(r.vibration_energy, 0.0);
  return r;
}

// Trapezoidal rule, amplitude 0.03 (1% of the sag), dt = T1 / 40: measured error 1.7e-4 of the
// vibration energy over the 100 periods. Tolerance 5e-4. (Measured for orientation: amplitude 0.1
// gives 1.7e-2 at T1 / 40 and 2.5e-3 at T1 / 100; the error is the scheme's, not round-off.)
TEST(Newmark, SwingingCableConservesEnergy) {
  const SwingResult r = swingCable(0.03, 0.0);
  EXPECT_LT(r.largest_error / r.vibration_energy, 5e-4);
}

// HHT alpha = -0.05 at amplitude 0.3, where the trapezoidal rule blows up: the energy never rises
// above its start (tolerance 1e-8 of the vibration energy, the Newton tolerance) and loses less
// than half of the vibration energy over 100 periods (measured 38%: what the stiff axial modes
// take from the swing is damped out).
TEST(Newmark, HhtAlphaKeepsLargeSwingBounded) {
  const SwingResult r = swingCable(0.3, -0.05);
  EXPECT_LT(r.largest_gain / r.vibration_energy, 1e-8);
  EXPECT_LT(r.largest_error / r.vibration_energy, 0.5);
}

}  // namespace
}  // namespace flexmoor::test
