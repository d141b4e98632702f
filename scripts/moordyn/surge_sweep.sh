#!/usr/bin/env bash
# MoorDyn-C on a flexmoor surge case at several resolutions: for each "SEGMENTS DTM" pair, the
# MoorDyn input written from the case (write_input.py), 600 s of the case's surge driven by
# surge_driver (built against an installed MoorDyn-C, see its header), and one line of the
# fairlead tension extremes over t >= 100 s (records every 0.1 s) and the CPU of the steps.
# Usage: scripts/moordyn/surge_sweep.sh CASE DRIVER "20 0.004" "40 0.002" ...
#   e.g. scripts/moordyn/surge_sweep.sh cases/ocean/oc4-semi-surge.yaml /tmp/md/surge_driver \
#        "80 0.002" "160 0.0005"
set -euo pipefail
cd "$(dirname "$0")/../.."
case=$1 driver=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "segments,dtM_s,cpu_init_s,cpu_steps_s,end_min_1,end_max_1,end_min_2,end_max_2,end_min_3,end_max_3,fairten_min_1,fairten_max_1,fairten_min_2,fairten_max_2,fairten_min_3,fairten_max_3"
for resolution in "$@"; do
  read -r segments dtm <<<"$resolution"
  /usr/bin/python3 scripts/moordyn/write_input.py "$case" "$segments" "$dtm" >"$work/lines.txt"
  (cd "$work" && "$driver" lines.txt 600 "$dtm" >out.txt 2>err.txt) ||
    { echo "$segments,$dtm,failed: $(grep -m1 -o 't = [0-9.]* s.*' "$work/err.txt")"; continue; }
  /usr/bin/python3 - "$segments" "$dtm" "$work/out.txt" <<'EOF'
import re, sys
text = open(sys.argv[3]).read()
cpu = re.search(r"CPU init ([\d.]+) s, steps ([\d.]+) s", text).groups()
rows = re.findall(r"end_tension min (\d+) max (\d+) N; FairTen min (\d+) max (\d+) N", text)
print(",".join([sys.argv[1], sys.argv[2], *cpu] + [v for r in rows for v in r[:2]] +
               [v for r in rows for v in r[2:]]))
EOF
done
