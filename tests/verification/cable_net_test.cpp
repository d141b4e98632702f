// Verification of the incremental Newton statics on a cable net (the capability of the
// dissertation's Example 2, whose geometry was lost): a square, doubly symmetric 3-D net whose
// answer can be proved independently, and the behaviour of a static solve that cannot converge.
//
// The net: four straight cables, two along x at y = +-b and two along y at x = +-b, each running
// from a support at -c to a support at +c and crossing the two others at the interior nodes
// (+-b, +-b, 0). Each cable is split at its crossings into an outer segment (unstretched length
// c - b), an inner one (2 b) and another outer one. The supports are pinned, and pretension comes
// from prescribed support displacements: each support moves outwards along its cable by delta.
// Every interior node carries a load P in -z. Units kip, ft (Example 2's EA = 3.6e6 ksf x 0.01
// ft^2 and P = 13.608 kip).
//
// Two procedures reach the same state. Ramped (Example 2's): the support displacements and the
// loads grow together with the load factor, in four increments from the unstressed net; this
// needs one element per segment, because an interior node must get transverse stiffness from
// its stretched outer elements in the first iteration. Pretension first: the support
// displacements are held at full value (a constant history) and solved at load factor 0, then
// the loads follow in four increments.
//
// Exact solution. The net is symmetric under x -> -x, y -> -y and x <-> y, so the interior node
// (b, b) moves by (d, d, -w) and the others by the mirror images. Its outer x-cable segment runs to
// the support (c + delta, b, 0): r = (c + delta - b - d, -d, w), length l_o, stretch
// lambda_o = l_o / (c - b); its inner segment has length 2 (b + d), stretch (b + d) / b; tension
// T(lambda) = EA lambda (lambda^2 - 1) / 2 (flexmoor's law, Eq. 2.53). The y-cable is the mirror
// image. Equilibrium of the node:
//   x:  T_o (c + delta - b - 2 d) / l_o - T_i = 0   (both cables' outer segments, x-cable's inner)
//   z:  2 T_o w / l_o - P = 0
// For each w the x equation is solved for d (Brent; it decreases in d), then the z equation for w
// (Brent). Tolerance of the comparison: 1e-8 relative on w, d and the member forces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/model/time_function.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "tests/support/cable_models.hpp"
#include "tests/support/elastic_catenary.hpp"
#include "tests/support/scalar_root.hpp"

namespace flexmoor::test {
namespace {

struct NetInputs {
  double b = 10.0;       // ft, interior nodes at (+-b, +-b)
  double c = 25.0;       // ft, supports at +-c along each cable
  double E = 3.6e6;      // ksf
  double area = 0.01;    // ft^2
  double pull = 0.05;    // delta, ft: support displacement outwards along the cable
  double load = 13.608;  // P, kip at every interior node
  double EA() const { return E * area; }
};

struct NetSolution {
  double deflection;     // w
  double spread;         // d: the node moves away from the centre by d in x and in y
  double outer_tension;  // T_o
  double inner_tension;  // T_i
};

NetSolution solveNetExactly(const NetInputs& n) {
  const double reach = n.c + n.pull - n.b;  // x distance from the undisplaced node to the support
  const auto outer = [&](double w, double d) {
    const double l = std::sqrt((reach - d) * (reach - d) + d * d + w * w);
    return std::array<double, 2>{greenStrainTension(l / (n.c - n.b), n.EA()), l};
  };
  const auto inner = [&](double d) { return greenStrainTension((n.b + d) / n.b, n.EA()); };
  const auto spread = [&](double w) {
    return findRoot(
        [&](double d) {
          const auto [T, l] = outer(w, d);
          return T * (reach - 2.0 * d) / l - inner(d);
        },
        -0.5 * n.b, 0.5 * reach);
  };
  const double w = findRoot(
      [&](double w) {
        const auto [T, l] = outer(w, spread(w));
        return 2.0 * T * w / l - n.load;
      },
      0.0, n.c);
  const double d = spread(w);
  return {w, d, outer(w, d)[0], inner(d)};
}

struct Net {
  std::unique_ptr<model::Model> model;
  std::array<int, 4> interior;  // (b, b), (-b, b), (-b, -b), (b, -b)
};

enum class Procedure { Ramped, PretensionFirst };

// `per_segment` two-node elements on every segment.
Net buildNet(const NetInputs& n, int per_segment, Procedure procedure) {
  Net net;
  net.model = std::make_unique<model::Model>();
  model::Model& m = *net.model;
  const double b = n.b;
  net.interior = {m.addNode({b, b, 0.0}), m.addNode({-b, b, 0.0}), m.addNode({-b, -b, 0.0}),
                  m.addNode({b, -b, 0.0})};
  const element::CableSection section =
      linearElasticSection(n.E, n.area, 0.0, material::Compression::Carry);
  const std::shared_ptr<const model::TimeFunction> held =
      procedure == Procedure::Ramped ? nullptr
                                     : std::make_shared<model::TableFunction>(
                                           std::vector<double>{0.0}, std::vector<double>{1.0});
  // One cable: along axis `along` (0 = x, 1 = y) at the other coordinate `at`, through the two
  // interior nodes `first` (at -b) and `second` (at +b).
  const auto cable = [&](int along, double at, int first, int second) {
    Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
    low(along) = -n.c;
    high(along) = n.c;
    low(1 - along) = high(1 - along) = at;
    const int start = m.addNode(low), end = m.addNode(high);
    pin(m, start);
    pin(m, end);
    m.constrain(start, along, -n.pull, held);
    m.constrain(end, along, n.pull, held);
    addStraightCable(m, start, first, per_segment, 2, section);
    addStraightCable(m, first, second, per_segment, 2, section);
    addStraightCable(m, second, end, per_segment, 2, section);
  };
  const auto& i = net.interior;
  cable(0, b, i[1], i[0]);
  cable(0, -b, i[2], i[3]);
  cable(1, b, i[3], i[0]);
  cable(1, -b, i[2], i[1]);
  for (int node : net.interior) m.addNodalLoad(node, {0.0, 0.0, -n.load});
  m.numberEquations();
  return net;
}

// Four increments to load factor 1. Full Newton: |du|/|u| < 1e-8 and |R|/|P| < 1e-11; with
// quadratic convergence the error left after the last step is of the order of its square, so
// the state is exact well within the 1e-8 of the comparison. Modified Newton converges linearly,
// so it is held to the residual, 1e-12.
solve::StaticOptions fourIncrements(solve::NewtonFlavour flavour) {
  solve::StaticOptions o;
  o.increments = 4;
  o.flavour = flavour;
  const bool full = flavour == solve::NewtonFlavour::Full;
  o.stiffness_update = full ? 1 : 1000;
  o.max_iterations = full ? 50 : 500;
  o.convergence.displacement_tolerance = full ? 1e-8 : 1e-10;
  o.convergence.residual_tolerance = full ? 1e-11 : 1e-12;
  return o;
}

struct NetRun {
  solve::StaticReport report;
  std::vector<std::vector<double>> corrections;  // per increment, |du|/|u| of each iteration
  std::string iterations;                        // e.g. "6 3 3 3"
};

// Solves the net (after its pretension solve, for Procedure::PretensionFirst).
NetRun solveNet(const Net& net, Procedure procedure, model::State& state,
                const solve::StaticOptions& options) {
  const model::Assembler assembler(*net.model);
  if (procedure == Procedure::PretensionFirst) {
    solve::StaticOptions pretension = fourIncrements(solve::NewtonFlavour::Full);
    pretension.increments = 1;
    pretension.load_factor = 0.0;
    solve::solveStatic(assembler, state, pretension);
  }
  NetRun run;
  solve::SolveLog log;
  log.iteration = [&](const solve::IterationRecord& r) {
    if (static_cast<int>(run.corrections.size()) < r.increment) run.corrections.emplace_back();
    run.corrections.back().push_back(r.displacement_norm);
  };
  run.report = solve::solveStatic(assembler, state, options, log);
  std::ostringstream s;
  for (const auto& inc : run.report.increments) s << (s.tellp() > 0 ? " " : "") << inc.iterations;
  run.iterations = s.str();
  return run;
}

// Compares the converged net with the exact solution (1e-8 relative): every interior node's
// displacement by symmetry, and every member force.
void expectExactNet(const NetInputs& n, const Net& net, const model::State& state) {
  const NetSolution exact = solveNetExactly(n);
  const std::array<Eigen::Vector2d, 4> sign = {Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1),
                                               Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1)};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d u = state.displacement.col(net.interior[k]);
    EXPECT_NEAR(-u.z(), exact.deflection, 1e-8 * exact.deflection) << "interior node " << k;
    EXPECT_NEAR(u.x(), sign[k].x() * exact.spread, 1e-8 * std::abs(exact.spread)) << "node " << k;
    EXPECT_NEAR(u.y(), sign[k].y() * exact.spread, 1e-8 * std::abs(exact.spread)) << "node " << k;
  }
  // An element is on an inner segment when all its nodes lie within the square |x|, |y| <= b.
  const model::Model& m = *net.model;
  const model::Assembler assembler(m);
  const std::vector<element::ElementResult> results = assembler.elementResults(state);
  int inner = 0;
  for (int e = 0; e < m.elementCount(); ++e) {
    bool is_inner = true;
    for (int node : m.element(e).nodes())
      is_inner = is_inner && m.reference().col(node).head<2>().cwiseAbs().maxCoeff() <= n.b + 1e-9;
    inner += is_inner;
    const double expected = is_inner ? exact.inner_tension : exact.outer_tension;
    for (double t : {results[e].end_tension[0], results[e].end_tension[1]})
      EXPECT_NEAR(t, expected, 1e-8 * expected) << "element " << e;
  }
  EXPECT_EQ(3 * inner, m.elementCount());  // one inner and two outer segments per cable
}

// Example 2's procedure (ramped): four equal increments of full Newton (tangent every iteration)
// from the unstressed net. The answer must match the exact solution to 1e-8 (displacements and
// member forces); full Newton must converge in at most 6 iterations per increment, and
// quadratically: once the correction max |du_i| / L (L the element size, Convergence) is below
// 1e-2, each one must be at most 150 times the square of the one before (measured: 128 at most),
// until round-off (1e-12); a tangent error that left linear convergence at a rate of 0.1 or
// slower would fail this. The dissertation's own tolerance (0.0025 on the increment, no residual
// check; it reports 5 iterations, then 3, for its lost net) is run too and its counts are
// recorded.
TEST(CableNet, FourIncrementsOfNewtonMatchSymmetricSolution) {
  const NetInputs inputs;
  const NetSolution exact = solveNetExactly(inputs);
  const Net net = buildNet(inputs, 1, Procedure::Ramped);
  model::State state = net.model->initialState();
  const NetRun run =
      solveNet(net, Procedure::Ramped, state, fourIncrements(solve::NewtonFlavour::Full));
  std::cout << "[ net ] w " << -state.displacement(2, net.interior[0]) << " ft (exact "
            << exact.deflection << "), d " << state.displacement(0, net.interior[0])
            << " ft (exact " << exact.spread << "), T_o " << exact.outer_tension << " kip, T_i "
            << exact.inner_tension
            << " kip\n[ net ] full Newton iterations per increment: " << run.iterations << "\n";
  for (const auto& c : run.corrections) {
    std::cout << "    |du|/|u|:";
    for (double x : c) std::cout << ' ' << x;
    std::cout << "\n";
  }
  ::testing::Test::RecordProperty("full_newton_iterations", run.iterations);
  expectExactNet(inputs, net, state);
  ASSERT_EQ(run.report.increments.size(), 4u);
  for (const auto& inc : run.report.increments)
    EXPECT_LE(inc.iterations, 6) << "increment " << inc.increment;
  for (const auto& c : run.corrections)
    for (size_t k = 0; k + 1 < c.size(); ++k)
      if (c[k] < 1e-2 && c[k + 1] > 1e-12) {
        EXPECT_LE(c[k + 1], 150.0 * c[k] * c[k]) << "iteration " << k + 2 << " is not quadratic";
      }

  model::State loose = net.model->initialState();
  solve::StaticOptions dissertation = fourIncrements(solve::NewtonFlavour::Full);
  dissertation.convergence.use_residual = false;
  dissertation.convergence.displacement_tolerance = 0.0025;
  const NetRun coarse = solveNet(net, Procedure::Ramped, loose, dissertation);
  std::cout << "[ net ] with the dissertation's tolerance 0.0025: " << coarse.iterations << "\n";
  ::testing::Test::RecordProperty("full_newton_iterations_tolerance_0.0025", coarse.iterations);
  EXPECT_NEAR(-loose.displacement(2, net.interior[0]), exact.deflection, 1e-3 * exact.deflection);
}

// Modified Newton (the tangent formed once, at the start of each increment) reaches the same
// answer (1e-8), with more iterations than full Newton in every increment. Both start from the
// pretensioned net: from the unstressed net the first tangent (inner segments unstressed) is far
// softer than the structure it must find, and modified Newton diverges there.
TEST(CableNet, ModifiedNewtonConvergesMoreSlowly) {
  const NetInputs inputs;
  for (const int per_segment : {1, 2}) {
    const Net net = buildNet(inputs, per_segment, Procedure::PretensionFirst);
    model::State full_state = net.model->initialState(), modified_state = full_state;
    const NetRun full = solveNet(net, Procedure::PretensionFirst, full_state,
                                 fourIncrements(solve::NewtonFlavour::Full));
    const NetRun modified = solveNet(net, Procedure::PretensionFirst, modified_state,
                                     fourIncrements(solve::NewtonFlavour::Modified));
    std::cout << "[ net, pretension first, " << per_segment
              << " element(s) per segment ] iterations per increment: full Newton "
              << full.iterations << ", modified Newton " << modified.iterations << "\n";
    ::testing::Test::RecordProperty("full_newton_iterations_" + std::to_string(per_segment),
                                    full.iterations);
    ::testing::Test::RecordProperty("modified_newton_iterations_" + std::to_string(per_segment),
                                    modified.iterations);
    expectExactNet(inputs, net, full_state);
    expectExactNet(inputs, net, modified_state);
    for (int k = 0; k < 4; ++k) {
      EXPECT_LE(full.report.increments[k].iterations, 6);
      EXPECT_EQ(modified.report.increments[k].tangent_updates, 1);
      EXPECT_GT(modified.report.increments[k].iterations, full.report.increments[k].iterations);
    }
  }
}

// A solve that cannot converge (one Newton iteration allowed, a tolerance no single iteration
// meets) throws ConvergenceError and hands back the state of the last converged increment, bit
// for bit: here the net converged at load factor 0.5.
TEST(StaticSolver, DivergentSolveThrowsAndKeepsLastConvergedState) {
  const NetInputs inputs;
  const Net net = buildNet(inputs, 1, Procedure::Ramped);
  const model::Assembler assembler(*net.model);
  model::State state = net.model->initialState();
  solve::StaticOptions half = fourIncrements(solve::NewtonFlavour::Full);
  half.load_factor = 0.5;
  half.increments = 2;
  solve::solveStatic(assembler, state, half);
  const model::State converged = state;

  solve::StaticOptions strict = fourIncrements(solve::NewtonFlavour::Full);
  strict.max_iterations = 1;
  strict.convergence.displacement_tolerance = 1e-14;
  strict.convergence.residual_tolerance = 1e-15;
  EXPECT_THROW(solve::solveStatic(assembler, state, strict), solve::ConvergenceError);
  EXPECT_EQ(state.load_factor, 0.5);
  EXPECT_TRUE((state.displacement.array() == converged.displacement.array()).all());
}

// A mechanism: a rope (tension-only) pushed at its free end has no stiffness once it goes
// slack, so the solve must throw ConvergenceError and leave the start state (nothing converged).
TEST(StaticSolver, PushedRopeIsAMechanism) {
  model::Model m;
  const int anchor = m.addNode(Eigen::Vector3d::Zero());
  const int end = m.addNode(Eigen::Vector3d(10.0, 0.0, 0.0));
  const std::vector<int> nodes =
      addStraightCable(m, anchor, end, 4, 2,
                       linearElasticSection(1.0e6, 0.1, 0.0, material::Compression::TensionOnly));
  pin(m, anchor);
  for (int n : nodes) {
    m.constrain(n, 1);
    m.constrain(n, 2);
  }
  m.addNodalLoad(end, Eigen::Vector3d(-5.0, 0.0, 0.0));
  m.numberEquations();
  const model::Assembler assembler(m);
  model::State state = m.initialState();
  EXPECT_THROW(solve::solveStatic(assembler, state, solve::StaticOptions{}),
               solve::ConvergenceError);
  EXPECT_EQ(state.load_factor, 0.0);
  EXPECT_TRUE(state.displacement.isZero(0.0));
}

}  // namespace
}  // namespace flexmoor::test
