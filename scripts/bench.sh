#!/usr/bin/env bash
# Builds the Google Benchmark harness in build-bench/ (Release) and runs it; prints, for every
# benchmark family, the time per operation at each size and the growth exponent between sizes
# (log t2/t1 / log n2/n1). Extra arguments go to flexmoor_bench (e.g. --benchmark_filter=Cable).
# Targets: cable chains <= N^1.15, membrane meshes <= N^1.5, a 1,000-dof cable Newton
# iteration < 1 ms. The figures are recorded in docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DFLEXMOOR_BENCH=ON >/dev/null
cmake --build build-bench -j"$(nproc)" --target flexmoor_bench >/dev/null
json=$(mktemp)
trap 'rm -f "$json"' EXIT
build-bench/bin/flexmoor_bench --benchmark_min_time=0.2 --benchmark_format=json "$@" >"$json"
python3 scripts/bench_exponents.py "$json"
