#!/usr/bin/env bash
# Fresh machine to a full test run: set up, build, run every test with ctest; then the suite
# again built with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/: gcc as for the
# Release tree, -O1 with line tables only (-g1: stacks still name file and line, and it builds
# faster), assertions on), where any memory error, leak, undefined behaviour or failed assertion
# fails the test that meets it.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache hits from any checkout: paths relative to the checkout, and the build directory left out
# of the hash of the -g sanitizer tree (only its debug info's compilation directory may be stale).
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD} CCACHE_NOHASHDIR=1
bash scripts/setup.sh
jobs=$(nproc 2>/dev/null || echo 2)
ctest --test-dir build --output-on-failure -j"$jobs"

echo "flexmoor test: the suite under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/)"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DFLEXMOOR_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$jobs"
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Under the sanitizers, the suite less what would only repeat there, at length, code paths the
# shorter tests run there already: the full-length comparisons of numbers (MoorDyn's OC3, OC4 and
# Example 8, adaptive steps over 200 s of OC4, the new users' cases, the C host's 120 s) and the
# figure tests, whose time is matplotlib's. The Release tree runs them all.
long_runs='^(MoorDynComparison|AdaptiveStepsOc4|NewUserDefaults|CApiHost|Plot|PlotFigures|PlotFailures|PlotAxes|PlotFigureContent|MooringFigure|CaseFigure)[.]'
ctest --test-dir build-asan --output-on-failure -j"$jobs" -E "$long_runs"
