// Time per Newton iteration (element sweep + factorisation + solve) and per Newmark time step
// against problem size, with the memory of the tangent and its factor per dof.
// Run: scripts/bench.sh (builds build-bench/, prints the growth exponents); docs/performance.md
// records the figures.
#include <benchmark/benchmark.h>

#include <cmath>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/linear_solver.hpp"
#include "libstruct/solve/newmark.hpp"

namespace {

using namespace flexmoor;

// A taut chain of `elements` cable elements of `order` nodes along x, both ends pinned, sagged
// by a small transverse displacement so every element is stressed.
struct CableChain {
  model::Model model;
  model::State state;

  CableChain(int elements, int order) {
    const int nodes = elements * (order - 1) + 1;
    const double length = 100.0;
    for (int i = 0; i < nodes; ++i) model.addNode({length * i / (nodes - 1), 0.0, 0.0});
    element::CableSection section{
        0.01, 7850.0,
        std::make_shared<material::LinearElasticCable>(2e11, material::Compression::Carry)};
    for (int e = 0; e < elements; ++e) {
      std::vector<int> n;
      for (int k = 0; k < order; ++k) n.push_back(e * (order - 1) + k);
      model.addElement(element::makeCableElement(n, section));
    }
    for (int k = 0; k < 3; ++k) {
      model.constrain(0, k);
      model.constrain(nodes - 1, k, k == 0 ? 0.01 : 0.0);
    }
    model.numberEquations();
    state = model.initialState();
    state.load_factor = 1.0;
    for (int i = 0; i < nodes; ++i) {
      const double x = static_cast<double>(i) / (nodes - 1);
      state.displacement(0, i) = 0.01 * x;
      state.displacement(1, i) = 0.1 * x * (1.0 - x);
      state.displacement(2, i) = -0.5 * x * (1.0 - x);
    }
  }
};

// A flat square membrane of n x n Q4 elements, edges pinned, biaxially stretched by 1% and lifted
// into a dome so every element is stressed and curved.
struct MembraneSheet {
  model::Model model;
  model::State state;

  explicit MembraneSheet(int n) {
    const int side = n + 1;
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) model.addNode({double(i) / n, double(j) / n, 0.0});
    element::MembraneSection section{
        0.001, 1000.0, std::make_shared<material::LinearElasticPlaneStress>(1e7, 0.3)};
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = j * side + i;
        model.addElement(
            element::makeMembraneElement("quad", {a, a + 1, a + side + 1, a + side}, section));
      }
    state = model.initialState();
    for (int k = 0; k < model.nodeCount(); ++k) {
      const double x = model.reference()(0, k), y = model.reference()(1, k);
      const bool edge = x == 0.0 || y == 0.0 || x == 1.0 || y == 1.0;
      for (int c = 0; c < 3; ++c)
        if (edge) model.constrain(k, c, c < 2 ? 0.01 * model.reference()(c, k) : 0.0);
      state.displacement.col(k) << 0.01 * x, 0.01 * y, 0.05 * x * (1 - x) * y * (1 - y);
    }
    model.numberEquations();
    state.load_factor = 1.0;
  }
};

template <class Structure>
void newtonIteration(benchmark::State& bench, Structure& structure) {
  model::Assembler assembler(structure.model);
  solve::LinearSolver linear;
  model::SparseMatrix K;
  // The sparsity pattern and CHOLMOD's symbolic analysis are made once per model, as in a run;
  // the timed iterations are what every Newton iteration repeats.
  linear.factorize((solve::outOfBalance(assembler, structure.state, &K), K));
  for (auto _ : bench) {
    const solve::Residual R = solve::outOfBalance(assembler, structure.state, &K);
    linear.factorize(K);
    benchmark::DoNotOptimize(linear.solve(R.free));
  }
  const double dofs = assembler.equationCount();
  bench.counters["dofs"] = dofs;
  // Memory: stored entries of K and of its Cholesky factor, per dof (constant = linear memory).
  bench.counters["K_nnz_per_dof"] = K.nonZeros() / dofs;
  bench.counters["L_nnz_per_dof"] = linear.factorNonzeros() / dofs;
  bench.SetComplexityN(assembler.equationCount());
}

void NewtonIterationMembraneSheet(benchmark::State& bench) {
  MembraneSheet sheet(static_cast<int>(std::sqrt(bench.range(0) / 3.0)));
  newtonIteration(bench, sheet);
}
BENCHMARK(NewtonIterationMembraneSheet)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Complexity()
    ->Unit(benchmark::kMicrosecond);

void NewtonIterationCableChain(benchmark::State& bench) {
  CableChain chain(static_cast<int>(bench.range(0)) / 3, 2);
  newtonIteration(bench, chain);
}
BENCHMARK(NewtonIterationCableChain)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMicrosecond);

void ElementSweepCableChain(benchmark::State& bench) {
  CableChain chain(static_cast<int>(bench.range(0)) / 3, 2);
  model::Assembler assembler(chain.model);
  model::SparseMatrix K;
  Eigen::VectorXd F;
  for (auto _ : bench) {
    assembler.internalForce(chain.state, F, &K);
    benchmark::DoNotOptimize(F.data());
  }
  bench.SetComplexityN(assembler.equationCount());
}
BENCHMARK(ElementSweepCableChain)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMicrosecond);

// Newmark time steps (trapezoidal rule, full Newton, the default convergence test: Eq. 5.1 and
// the residual) released from the stressed state: each benchmark iteration integrates kSteps
// steps from the same start, so the time per step includes the iterations a real step needs (the
// steps/s counter; its inverse is per step).
template <class Structure>
void newmarkSteps(benchmark::State& bench, Structure& structure, double dt) {
  constexpr int kSteps = 20;
  model::Assembler assembler(structure.model);
  solve::DynamicOptions o;
  o.schedule = {{dt, kSteps}};
  int iterations = 0;
  for (auto _ : bench) {
    model::State s = structure.state;
    iterations = solve::integrate(assembler, s, o).iterations;
  }
  bench.counters["dofs"] = assembler.equationCount();
  bench.counters["iterations_per_step"] = static_cast<double>(iterations) / kSteps;
  bench.counters["steps"] =
      benchmark::Counter(kSteps, benchmark::Counter::kIsIterationInvariantRate);
}

void TimeStepCableChain(benchmark::State& bench) {
  CableChain chain(static_cast<int>(bench.range(0)) / 3, 2);
  newmarkSteps(bench, chain, 1e-3);
}
BENCHMARK(TimeStepCableChain)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Unit(benchmark::kMillisecond);

void TimeStepMembraneSheet(benchmark::State& bench) {
  MembraneSheet sheet(static_cast<int>(std::sqrt(bench.range(0) / 3.0)));
  newmarkSteps(bench, sheet, 1e-3);
}
BENCHMARK(TimeStepMembraneSheet)
    ->RangeMultiplier(10)
    ->Range(100, 100000)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
