"""Opens a run's netCDF with xarray as a user would and checks that its records select: `time`
(the dynamic steps' records) is strictly increasing, so ds.sel(time=t) picks one record, exactly
at a stored time and with method='nearest' at that time rounded to 1e-9 s (the tolerance covers
t0 + n dt summed in floating point until the integrator makes such times exact); `stage` (the
states closing the other steps, by step number) is strictly increasing and selects the same
way; `end` is a coordinate, sel(end=1) the first end, not the last.

Usage: /usr/bin/python3 xarray_records_check.py FILE.nc
Prints one line per check and exits 1 on the first that fails.
"""
import sys

import numpy as np
import xarray as xr


def require(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        sys.exit(1)


path = sys.argv[1]
ds = xr.open_dataset(path)
# A field the file has (a case's output: fields: may leave some out), under time and stage.
field = next(v for v in ("displacement_z", "position_z", "velocity_z", "tension_end") if v in ds)
require("time" in ds.indexes and "stage" in ds.indexes, "time and stage are index coordinates")
t = ds.time.values
require(np.all(np.diff(t) > 0), "time is strictly increasing (%d records)" % t.size)
require(ds.indexes["time"].is_unique, "time is unique")
for k in sorted({0, t.size // 2, t.size - 1}) if t.size else []:
    exact = ds.sel(time=t[k])
    require("time" not in exact[field].dims and
            np.array_equal(exact[field].values, ds[field].isel(time=k).values, equal_nan=True),
            "sel(time=%r) is record %d" % (float(t[k]), k))
    nominal = round(float(t[k]), 9)
    near = ds.sel(time=nominal, method="nearest", tolerance=1e-9 * max(1.0, abs(nominal)))
    require(float(near.time) == t[k], "sel(time=%g, method='nearest') is record %d" % (nominal, k))
stage = ds.stage.values
require(np.all(np.diff(stage) > 0), "stage is strictly increasing (%d records)" % stage.size)
for k, number in enumerate(stage):
    one = ds.sel(stage=number)
    require("stage" not in one["stage_" + field].dims and
            np.array_equal(one["stage_" + field].values,
                           ds["stage_" + field].isel(stage=k).values, equal_nan=True),
            "sel(stage=%d) is the state closing step %d (%s)" % (number, number,
                                                                  str(one.stage_step.values)))
require(list(ds.end.values) == [1, 2], "end is a coordinate of 1 and 2")
if "tension_end" in ds and t.size:
    require(np.array_equal(ds.tension_end.sel(end=1).values,
                           ds.tension_end.isel(end=0).values, equal_nan=True),
            "sel(end=1) is the elements' first end")
print("xarray selects the records of %s" % path)
