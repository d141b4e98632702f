// The cost of an irregular sea's kinematics: Sea::at at one point against the number of
// components (10 to 1,000), without and with the position gradient (what the Morison loads'
// Jacobian asks for), and Sea::elevation alone. A JONSWAP sea (Hs 6 m, Tp 10 s, random bins,
// seed 1) in 200 m of water, Wheeler stretching, the point 10 m below the mean level and moving
// on (x and t change every call, as a line's points do). Run: scripts/bench.sh
// --benchmark_filter=Sea; docs/performance.md records the figures.
#include <benchmark/benchmark.h>

#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/wave_synthesis.hpp"

namespace {

using namespace flexmoor::hydro;

Sea jonswapSea(int components) {
  SynthesisOptions o;
  o.components = components;
  Sea sea(Water{1025.0, 200.0, 9.80665});
  for (const WaveComponent& c :
       synthesise(WaveSpectrum::jonswap(6.0, 10.0, 3.3), o, 200.0, 9.80665).components)
    sea.addComponent(c);
  return sea;
}

// range(0): components; range(1): 0 = values, 1 = values and gradient, 2 = elevation only.
void SeaAtPoint(benchmark::State& state) {
  const int components = static_cast<int>(state.range(0));
  const Sea sea = jonswapSea(components);
  Eigen::Vector3d x(0.0, 3.0, -10.0);
  double t = 0.0;
  FluidGradient g;
  for (auto _ : state) {
    x.x() += 0.37;
    t += 0.1;
    if (state.range(1) == 2) {
      benchmark::DoNotOptimize(sea.elevation(x, t));
    } else if (state.range(1) == 1) {
      benchmark::DoNotOptimize(sea.at(x, t, g));
      benchmark::DoNotOptimize(g);
    } else {
      benchmark::DoNotOptimize(sea.at(x, t));
    }
  }
  state.counters["ns_per_component"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * components,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["n"] = components;
}
BENCHMARK(SeaAtPoint)
    ->ArgsProduct({{10, 30, 100, 300, 1000}, {0, 1, 2}})
    ->ArgNames({"components", "mode"});

}  // namespace
