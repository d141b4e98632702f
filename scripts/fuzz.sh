#!/usr/bin/env bash
# Fuzzes the case reader with libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer:
#   bash scripts/fuzz.sh [SECONDS]      (default 600; one process in the foreground)
# Builds build-fuzz/ with clang (FLEXMOOR_FUZZ=ON), seeds the corpus from every case under cases/
# and runs tests/fuzz/case_reader_fuzz with the case-key dictionary tests/fuzz/yaml.dict. A crash,
# sanitizer report, leak, time-out (10 s for one input) or a run past 2 GB is a finding: libFuzzer
# stops, writes the input as build-fuzz/findings/crash-*|leak-*|timeout-*|oom-* and this script
# exits non-zero. Extra arguments after SECONDS go to libFuzzer (for example a corpus to replay).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true

export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DFLEXMOOR_FUZZ=ON >/dev/null
cmake --build build-fuzz -j2 --target case_reader_fuzz

corpus=build-fuzz/corpus
mkdir -p "$corpus" build-fuzz/findings
find cases -name '*.yaml' -exec cp {} "$corpus"/ \;

export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
build-fuzz/bin/case_reader_fuzz "$corpus" -dict=tests/fuzz/yaml.dict -max_len=16384 \
  -timeout=10 -rss_limit_mb=2048 -max_total_time="$seconds" \
  -print_final_stats=1 -artifact_prefix=build-fuzz/findings/ "$@"
