#!/usr/bin/python3
"""CPU time (user + system) and wall-clock time of commands run in turn:
[--fresh] N CMD_A [-- CMD_B ...].

Each command runs N times, interleaved with the others (A B A B ...), so a drift of the
machine's speed reaches all of them alike; the time of each run is its own rusage (os.wait4),
and its wall clock from start to exit. With --fresh, the directory after a command's -o is
removed before each of its runs and the file systems synced, outside the timing (a rerun into the
same directory also pays for unlinking the earlier files). Prints the minimum and the median of each, in ms:

    /usr/bin/python3 scripts/cpu_runs.py 15 ./flexmoor.base run CASE -o a --no-vtk --no-figure \\
        -- build/bin/flexmoor run CASE -o b --no-vtk --no-figure
"""
import os
import shutil
import statistics
import subprocess
import sys
import time

arguments = sys.argv[1:]
fresh = bool(arguments) and arguments[0] == "--fresh"
if fresh:
    arguments = arguments[1:]
if len(arguments) < 2:
    sys.exit(__doc__)
runs = int(arguments[0])
commands = [c.split() for c in " ".join(arguments[1:]).split(" -- ")]
times = [[] for _ in commands]
walls = [[] for _ in commands]
for _ in range(runs):
    for command, spent, wall in zip(commands, times, walls):
        if fresh and "-o" in command:
            shutil.rmtree(command[command.index("-o") + 1], ignore_errors=True)
            os.sync()  # the removal's deferred work is not the next run's
        start = time.perf_counter()
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        wall.append(1000.0 * (time.perf_counter() - start))
        if status != 0:
            sys.exit(f"{' '.join(command)}: exit status {status}")
        spent.append(1000.0 * (usage.ru_utime + usage.ru_stime))
for command, spent, wall in zip(commands, times, walls):
    print(f"{' '.join(command)[:60]:60s} cpu min {min(spent):7.1f} median "
          f"{statistics.median(spent):7.1f} ms   wall min {min(wall):7.1f} median "
          f"{statistics.median(wall):7.1f} ms  ({runs} runs)")
