#!/usr/bin/env bash
# The C interface's cost per step over the command's in-process loop, on OC4 surge (600 s,
# 6,000 steps of 0.1 s): `flexmoor run oc4-semi-surge` against examples/c/platform_host.c driving
# the same platform motion through flexmoor.h (its results file is the command's to the bit;
# docs/validation.md CA6). Both on one core (taskset), so that both write their records in the
# run's own thread; RUNS runs of each, interleaved; prints the minimum CPU (user + system) of each
# and the difference per step. Figures recorded in docs/performance.md.
#   bash scripts/bench_c_api.sh [RUNS]   (default 5; build/ built first)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cpu() {  # CPU seconds (user + system) of a command
  local t
  t=$( { /usr/bin/time -f "%U %S" "$@" >/dev/null 2>/dev/null; } 2>&1 | tail -1)
  awk '{print $1 + $2}' <<<"$t"
}
best_command=1e9
best_host=1e9
for ((k = 0; k < runs; ++k)); do
  c=$(cpu taskset -c 0 build/bin/flexmoor run oc4-semi-surge --no-figure -o "$out/command")
  h=$(cpu taskset -c 0 build/bin/platform_host oc4-semi-surge -o "$out/host")
  best_command=$(awk -v a="$best_command" -v b="$c" 'BEGIN {print (b < a) ? b : a}')
  best_host=$(awk -v a="$best_host" -v b="$h" 'BEGIN {print (b < a) ? b : a}')
done
awk -v c="$best_command" -v h="$best_host" 'BEGIN {
  printf "command: %.3f s CPU, C interface: %.3f s CPU (minima of the runs)\n", c, h
  printf "difference: %+.1f%% of the run, %+.2f us a step (6,000 steps)\n", 100 * (h - c) / c, 1e6 * (h - c) / 6000
}'
