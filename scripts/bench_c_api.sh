#!/usr/bin/env bash
# The C interface's cost per step over the command's in-process loop, on OC4 surge (600 s,
# 6,000 steps of 0.1 s): `flexmoor run oc4-semi-surge` against examples/c/platform_host.c, which
# drives the same platform motion through flexmoor.h step by step and reads the platform's loads
# after each (its results file is the command's to the bit: docs/validation.md, CA6). Both on one
# core (taskset), so that both write their records in the run's own thread, RUNS runs each,
# interleaved (scripts/cpu_runs.py); the difference of the CPU minima over 6,000 steps is the
# interface's cost a step. Figures recorded in docs/performance.md ("The C interface").
#   bash scripts/bench_c_api.sh [RUNS]   (default 7; build/ built first)
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
/usr/bin/python3 scripts/cpu_runs.py --fresh "${1:-7}" \
  taskset -c 0 build/bin/flexmoor run oc4-semi-surge --no-figure -o "$out/command" -- \
  taskset -c 0 build/bin/platform_host oc4-semi-surge -o "$out/host"
