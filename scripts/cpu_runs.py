#!/usr/bin/python3
"""CPU time (user + system) of commands run in turn: N CMD_A [-- CMD_B ...].

Each command runs N times, interleaved with the others (A B A B ...), so a drift of the
machine's speed reaches all of them alike; the time of each run is its own rusage (os.wait4),
not the wall clock. Prints the minimum and the median of each, in ms:

    /usr/bin/python3 scripts/cpu_runs.py 15 ./flexmoor.base run CASE -o a --no-vtk --no-figure \\
        -- build/bin/flexmoor run CASE -o b --no-vtk --no-figure
"""
import os
import statistics
import subprocess
import sys

if len(sys.argv) < 3:
    sys.exit(__doc__)
runs = int(sys.argv[1])
commands = [c.split() for c in " ".join(sys.argv[2:]).split(" -- ")]
times = [[] for _ in commands]
for _ in range(runs):
    for command, spent in zip(commands, times):
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        if status != 0:
            sys.exit(f"{' '.join(command)}: exit status {status}")
        spent.append(1000.0 * (usage.ru_utime + usage.ru_stime))
for command, spent in zip(commands, times):
    print(f"{' '.join(command)[:60]:60s} min {min(spent):8.1f} ms  "
          f"median {statistics.median(spent):8.1f} ms  ({runs} runs)")
