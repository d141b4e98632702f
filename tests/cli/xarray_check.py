"""Opens a flexmoor result with xarray as a user would and checks that CF metadata is honoured.

Usage: /usr/bin/python3 xarray_check.py FILE.nc [--mixed] [--per-radian]
Prints one line per check and exits 1 on the first that fails. --mixed: the file holds cables
and membranes, so tension_end must be finite on the cables and missing (NaN) on the membranes;
--per-radian: an axisymmetric meridian, whose reactions are per radian of circumference.
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
# The records read: the time axis (dynamic steps), or for a run without a dynamic step the stage
# records (the states closing its steps), whose variables are named stage_NAME.
dynamic = ds.sizes["time"] > 0
prefix, record = ("", "time") if dynamic else ("stage_", "stage")


def records(name):
    return ds[prefix + name]


require("time" in ds.indexes, "time is an index coordinate of the record dimension")
require(ds.time.attrs.get("standard_name") == "time" and ds.time.attrs.get("axis") == "T",
        "time has standard_name time and axis T")
require(ds.time.attrs.get("units") == "s" and np.issubdtype(ds.time.dtype, np.floating),
        "time stays a float in seconds (not decoded into dates)")
for name in ("node_x", "node_y", "node_z", "element_x", "step_number", "step_name",
             "load_factor", "stage_step", "stage_time", "stage_load_factor", "point_element"):
    require(name in ds.coords, name + " is found as a coordinate")
for name in ("node", "element", "end"):
    require(name in ds.indexes and int(ds[name][0]) == 1, name + " is a 1-based index")
require(set(records("displacement_x").coords) >=
        {record, "node", "node_x", "node_y", "node_z"},
        "%sdisplacement_x carries the %s and node coordinates" % (prefix, record))
require(set(records("tension_end").coords) >= {"element_x", "element_y", "element_z"},
        "%stension_end carries the element coordinates" % prefix)
missing_long_name = [v for v in ds.variables if "long_name" not in ds[v].attrs]
require(not missing_long_name, "every variable has a long_name " + str(missing_long_name))
names = ds.step_name if dynamic else ds.stage_step
require(isinstance(names.values[0], str), "%s reads as text" % names.name)

# A slice selects by its label: the last record of the run by its time value (or step number).
last = ds[record].values[-1]
by_label = records("displacement_z").sel({record: last})
require(record not in by_label.dims and
        np.array_equal(by_label.values, records("displacement_z").isel({record: -1}).values),
        "sel(%s=%g) selects the record of that %s" % (record, last, record))
if ds.sizes["time"] > 2:  # a time history: a window selects the records inside it
    t = ds.time.values
    lo, hi = t[len(t) // 3], t[2 * len(t) // 3]
    window = ds.displacement_z.sel(time=slice(lo, hi))
    require(window.sizes["time"] == int(((t >= lo) & (t <= hi)).sum()) > 0,
            "sel(time=slice(%g, %g)) selects the records of that window" % (lo, hi))
if "mode_shape_x" in ds:
    require(ds.mode_shape_x.attrs.get("units", "").endswith("^-0.5"),
            "mass-normalised mode shapes carry units of mass^-1/2")
require(np.array_equal(records("position_x").values,
                      records("displacement_x").values + ds.node_x.values),
        "position = reference coordinate + displacement, broadcast by node")

if "--mixed" in sys.argv:
    kinds = [str(t) for t in ds.element_type.values]
    cables = np.array([t.startswith("cable") for t in kinds])
    membranes = np.array([not t.startswith("cable") for t in kinds])
    ends = records("tension_end").isel({record: -1}).values
    require(cables.any() and membranes.any(), "the file has cables and membranes")
    require(np.isfinite(ends[cables]).all(), "tension_end is finite on every cable")
    require(np.isnan(ends[membranes]).all(), "tension_end is missing (NaN) on every membrane")
    resultant = records("membrane_resultant_max").isel({record: -1}).values
    require(np.isnan(resultant[cables]).all() and np.isfinite(resultant[membranes]).all(),
            "membrane resultants are missing on cables and present on membranes")
if "--per-radian" in sys.argv:
    require(ds.reaction_x.attrs.get("units", "").endswith("/rad"),
            "an axisymmetric meridian's reactions are per radian (%s)" % ds.reaction_x.attrs.get("units"))
print("xarray reads %s as intended" % path)
