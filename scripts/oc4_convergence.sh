#!/usr/bin/env bash
# One row of OC4's convergence table (docs/validation.md, "Dynamic spread moorings"): the named
# case cases/ocean/oc4-semi-surge.yaml with its elements a line, element order, time step and
# Newton tolerance changed, shortened to 200 s (statistics over 100-200 s, as the case's own),
# run, and its iterations and tension extremes printed on one line.
# Usage: scripts/oc4_convergence.sh ELEMENTS ORDER DT TOLERANCE [FLEXMOOR_BINARY]
#   e.g. scripts/oc4_convergence.sh 80 3 0.05 1e-6   # the reference
set -euo pipefail
cd "$(dirname "$0")/.."
elements=$1 order=$2 dt=$3 tolerance=$4
binary=${5:-build/bin/flexmoor}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$elements" "$order" "$dt" "$tolerance" >"$work/case.yaml" <<'EOF'
import re, sys
elements, order, dt, tolerance = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
text = open("cases/ocean/oc4-semi-surge.yaml").read()
text = re.sub(r"elements: \d+, order: \d", f"elements: {elements}, order: {order}", text)
text = re.sub(r"dt: [\d.]+ s, steps: \d+", f"dt: {dt:g} s, steps: {round(200 / dt)}", text)
text = re.sub(r"tolerance: [\d.e+-]+", f"tolerance: {tolerance}", text)
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
