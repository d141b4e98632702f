#!/usr/bin/env bash
# Output cost: runs the demo case cases/demo/driven-taut-cable.yaml stretched to 40,000
# time steps with a netCDF record every 1,000th, 4th and every step, and a mooring-line-sized
# cable (151 nodes) for 600 s at dt 0.01 s (60,000 steps) written every step, and prints the
# wall-clock and CPU time of each run. Targets (docs/performance.md, "Output cost"): writing every
# step costs under 10% of the demo run; the 600 s mooring run written every step costs under 10%
# more than the same run written every 1,000th step.
# Usage: scripts/bench_output.sh [FLEXMOOR_BINARY]   (default build/bin/flexmoor)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/bin/flexmoor}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The demo case with its dynamic step stretched to 40 + 39,960 steps, output every $1th step.
demo() {
  sed -e "s/name: driven-taut-cable/name: demo-every-$1/" \
      -e "s/{dt: 0.01 s, steps: 20}\],/{dt: 0.01 s, steps: 39960}],/" \
      -e "s/output_every: 4/output_every: $1/" cases/demo/driven-taut-cable.yaml
}

# The same wire as 150 linear (L2) elements (151 nodes, a mooring line's size), 600 s at dt 0.01 s.
mooring() {
  sed -e "s/name: driven-taut-cable/name: mooring-every-$1/" \
      -e "s/elements: 8, order: 2/elements: 150, order: 2/" \
      -e "s/schedule: \[.*\],/schedule: [{dt: 0.01 s, steps: 60000}],/" \
      -e "s/output_every: 4/output_every: $1/" cases/demo/driven-taut-cable.yaml
}

run() {  # $1 case file
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$work/time" "$binary" run "$1" -o "$work/out" --no-vtk >/dev/null
  end=$(date +%s.%N)
  read -r user sys <"$work/time"
  printf '%-22s wall %7.2f s   cpu %7.2f s   %s\n' "$(basename "$1" .yaml)" \
    "$(echo "$end - $start" | bc)" "$(echo "$user + $sys" | bc)" \
    "$(du -h "$work/out/$(basename "$1" .yaml).nc" | cut -f1)"
}

for every in 1000 4 1; do demo "$every" >"$work/demo-every-$every.yaml"; run "$work/demo-every-$every.yaml"; done
for every in 1000 1; do mooring "$every" >"$work/mooring-every-$every.yaml"; run "$work/mooring-every-$every.yaml"; done
