#!/usr/bin/env bash
# Fresh machine to a full test run: set up, build, run every test with ctest; then the same suite
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
ctest --test-dir build-asan --output-on-failure -j"$jobs"
