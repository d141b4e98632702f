#!/usr/bin/env bash
# One row of a surge case's convergence table (docs/validation.md, "Dynamic spread moorings"):
# the named case (cases/ocean/oc4-semi-surge.yaml or oc3-hywind-surge.yaml) with its elements a
# line, element order, time step and Newton tolerance changed, shortened to 200 s (statistics
# over 100-200 s, as the case's own), run, and its iterations and tension extremes printed on
# one line.
# Usage: scripts/surge_convergence.sh CASE ELEMENTS ORDER DT TOLERANCE [FLEXMOOR_BINARY]
#   e.g. scripts/surge_convergence.sh cases/ocean/oc4-semi-surge.yaml 80 3 0.05 1e-6
set -euo pipefail
cd "$(dirname "$0")/.."
case=$1 elements=$2 order=$3 dt=$4 tolerance=$5
binary=${6:-build/bin/flexmoor}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$case" "$elements" "$order" "$dt" "$tolerance" >"$work/case.yaml" <<'EOF'
import re, sys
case, elements, order, dt, tolerance = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), \
    float(sys.argv[4]), sys.argv[5]
text = open(case).read()
text = re.sub(r"elements: \d+, order: \d", f"elements: {elements}, order: {order}", text)
text = re.sub(r"dt: [\d.]+ s, steps: \d+", f"dt: {dt:g} s, steps: {round(200 / dt)}", text)
if "tolerance:" in text:
    text = re.sub(r"tolerance: [\d.e+-]+", f"tolerance: {tolerance}", text)
else:
    text = text.replace("criterion: displacement", f"criterion: displacement, tolerance: {tolerance}")
# The summary's fairlead ends: the last element of line k is k * elements.
ends = iter(range(1, 7))
text = re.sub(r"element: \d+, end: last",
              lambda m: f"element: {elements * ((next(ends) + 1) // 2)}, end: last", text)
print(text, end="")
EOF
"$binary" run "$work/case.yaml" -o "$work/out" --no-vtk --no-figure >"$work/log" 2>&1
printf '%s L%s dt %s tol %s: %s %s\n' "$elements" "$order" "$dt" "$tolerance" \
  "$(grep 'time steps' "$work/log")" \
  "$(grep -E 'tension_(min|max)_[12]|cpu_seconds' "$work/log" | awk '{printf "%s=%s ", $1, $2}')"
