#!/usr/bin/env bash
# The OC4 surge race against MoorDyn-C (docs/performance.md, "Mooring race"):
#  1. oc4-semi-surge: the named case's 600 s of surge, its CPU per simulated second against the
#     target of 5 ms (MoorDyn-C v2.7.1 on the same inputs: 3.4 ms at 40 segments, about as
#     accurate; docs/performance.md, MoorDyn-C on the same case);
#  2. cost against size: OC4's chain and water, N lines spread evenly around the platform
#     (3, 30, 300 lines of 20 L3 elements; 3 lines of 20, 100, 500 elements), each surged as in
#     the named case, results written every step. The time per step is the CPU of a run of
#     S2 steps less that of S1 steps (reading, the catenary start and the statics cancel), over
#     S2 - S1; the growth exponent between sizes is log(cost ratio) / log(dof ratio).
# Usage: scripts/bench_mooring.sh [FLEXMOOR_BINARY]   (default build/bin/flexmoor)
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/bin/flexmoor}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cpu() {  # $1 case file -> CPU seconds (user + system) of its run
  /usr/bin/time -f "%U %S" -o "$work/time" "$binary" run "$1" -o "$work/out" --no-vtk \
    --no-figure >/dev/null
  read -r user sys <"$work/time"
  echo "$user + $sys" | bc
}

echo "1. oc4-semi-surge, 600 s at dt 0.1 s, written every step"
total=$(cpu cases/ocean/oc4-semi-surge.yaml)
printf '   CPU %.2f s = %.2f ms per simulated second (target 5, MoorDyn 3.4 at 40 segments)\n' \
  "$total" "$(echo "$total * 1000 / 600" | bc -l)"

# A spread of $1 lines of $2 L3 elements, OC4's geometry turned to angle 2 pi k / N, surged for
# $3 steps of 0.1 s.
spread() {
  /usr/bin/python3 - "$1" "$2" "$3" <<'EOF'
import math, sys
lines, elements, steps = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
print("scenario: spread_mooring\ntitle: bench\nunits: SI")
print("water: {density: 1025 kg/m^3, depth: 200 m}\ngravity: 9.80665 m/s^2")
print("seabed: {stiffness: 3.0e6 Pa/m, damping: 3.0e5 Pa*s/m}")
print("line_types:\n  chain: {diameter: 0.0766 m, mass_per_length: 113.35 kg/m, EA: 7.536e8 N, "
      "Cn: 2.0, Ct: 0.4, Ca: 0.8, CaAx: 0.25, per_length: unstretched, "
      "damping: {BA: 3.052e6 N*s}}")
print("mooring_lines:")
for k in range(lines):
    a = math.pi + 2.0 * math.pi * k / lines
    print(f"  - {{anchor: [{837.6 * math.cos(a):.4f}, {837.6 * math.sin(a):.4f}, -200 m], "
          f"fairlead: [{40.868 * math.cos(a):.4f}, {40.868 * math.sin(a):.4f}, -14 m], "
          f"length: 835.35 m, type: chain, elements: {elements}, order: 3}}")
print("platform:\n  surge: {amplitude: 2.0 m, period: 10 s}")
print(f"dynamic: {{name: surge, dt: 0.1 s, steps: {steps}, hht_alpha: -0.1, "
      "criterion: displacement, load_matrices: iteration, output_every: 1}")
print("summary:\n  cpu_seconds: {quantity: cpu_seconds}")
EOF
}

s1=20
s2=120
echo "2. cost per time step against size ($((s2 - s1)) steps of 0.1 s)"
previous_dofs=""
previous_cost=""
for size in "3 20" "30 20" "300 20" "3 100" "3 500"; do
  read -r lines elements <<<"$size"
  if [ "$size" = "3 100" ]; then  # the second sweep grows the elements from 3 x 20
    previous_dofs=$base_dofs
    previous_cost=$base_cost
  fi
  spread "$lines" "$elements" "$s1" >"$work/short.yaml"
  spread "$lines" "$elements" "$s2" >"$work/long.yaml"
  short=$(cpu "$work/short.yaml")
  long=$(cpu "$work/long.yaml")
  dofs=$((lines * (2 * elements - 1) * 3))
  cost=$(echo "($long - $short) / ($s2 - $s1) * 1000" | bc -l)
  growth=""
  if [ -n "$previous_dofs" ]; then
    growth=$(printf 'growth exponent %.2f' \
      "$(echo "l($cost / $previous_cost) / l($dofs / $previous_dofs)" | bc -l)")
  else
    base_dofs=$dofs
    base_cost=$cost
  fi
  printf '   %3d lines x %3d L3: %7d dofs  %8.3f ms per step  %6.2f us per dof-step  %s\n' \
    "$lines" "$elements" "$dofs" "$cost" "$(echo "$cost * 1000 / $dofs" | bc -l)" "$growth"
  previous_dofs=$dofs
  previous_cost=$cost
done
