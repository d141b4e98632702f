#!/usr/bin/env bash
# The wall time of a study on 1 worker and on 2 (docs/performance.md, "Studies"): each run into
# a fresh directory, alternating, REPEATS times; prints one line a run and the ratio of the
# fastest 2-worker run to the fastest 1-worker run (the target: at most 0.55).
# Usage: scripts/study_speedup.sh [STUDY] [REPEATS] [FLEXMOOR_BINARY]
#   e.g. scripts/study_speedup.sh cases/studies/tube-rao.yaml 2
set -euo pipefail
cd "$(dirname "$0")/.."
study=${1:-cases/studies/tube-rao.yaml}
repeats=${2:-2}
binary=${3:-build/bin/flexmoor}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
best1="" best2=""
for r in $(seq "$repeats"); do
  for j in 1 2; do
    rm -rf "$work/out"
    start=$(date +%s.%N)
    "$binary" study "$study" -o "$work/out" -j "$j" >/dev/null
    wall=$(echo "$(date +%s.%N) - $start" | bc)
    load=$(cut -d' ' -f1 /proc/loadavg)
    echo "run $r, -j $j: wall $wall s (load average $load)"
    if [ "$j" = 1 ]; then
      if [ -z "$best1" ] || (( $(echo "$wall < $best1" | bc) )); then best1=$wall; fi
    else
      if [ -z "$best2" ] || (( $(echo "$wall < $best2" | bc) )); then best2=$wall; fi
    fi
  done
done
echo "fastest: 1 worker $best1 s, 2 workers $best2 s, ratio $(echo "scale=3; $best2 / $best1" | bc)"
