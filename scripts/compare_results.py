#!/usr/bin/python3
"""Compare the results of two runs of the same cases: DIR_A DIR_B (flexmoor run ... -o DIR).

For every <case>.summary.json in DIR_A: the largest relative difference of a summary key in
DIR_B. For every <case>.nc: the four variables that differ most, as max |a - b| / max |a|
(fill values ignored). What a speed change must leave alone, shown in numbers:

    /usr/bin/python3 scripts/compare_results.py out_base out_new
"""
import glob
import json
import os
import sys

import netCDF4
import numpy as np


def summaries(a, b):
    for path_a in sorted(glob.glob(os.path.join(a, "*.summary.json"))):
        ra = json.load(open(path_a))["results"]
        rb = json.load(open(os.path.join(b, os.path.basename(path_a))))["results"]
        worst = max((abs(ra[k] - rb[k]) / max(abs(ra[k]), 1e-300), k)
                    for k in ra if isinstance(ra[k], (int, float)))
        print(f"{os.path.basename(path_a)}: largest relative difference {worst[0]:.3g} ({worst[1]})")


def histories(a, b):
    for path_a in sorted(glob.glob(os.path.join(a, "*.nc"))):
        da = netCDF4.Dataset(path_a)
        db = netCDF4.Dataset(os.path.join(b, os.path.basename(path_a)))
        rows = []
        for name, va in da.variables.items():
            x = np.ma.filled(va[:], np.nan)
            if x.dtype.kind not in "fi" or x.size == 0:
                continue
            y = np.ma.filled(db[name][:], np.nan)
            if x.shape != y.shape:
                rows.append((np.inf, f"{name} (shape {x.shape} against {y.shape})"))
                continue
            largest = np.nanmax(np.abs(x))
            difference = np.nanmax(np.abs(x - y))
            rows.append((difference / largest if largest else difference, name))
        rows.sort(reverse=True)
        listed = ", ".join(f"{name} {d:.3g}" for d, name in rows[:4])
        print(f"{os.path.basename(path_a)}: {listed}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    summaries(sys.argv[1], sys.argv[2])
    histories(sys.argv[1], sys.argv[2])
