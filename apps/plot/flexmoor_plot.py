"""flexmoor plot: time-series figures (PNG) of a flexmoor result, drawn with matplotlib.

    /usr/bin/python3 flexmoor_plot.py RESULT.nc -o FIGURE.png [--series SPEC ...] [--title TEXT]

SPEC is VARIABLE@INDEX, one panel each, for example
    position_x@node=5            x of node 5 (1-based, as in the file's `node` coordinate)
    speed@node=5                 |velocity| of node 5 (derived from velocity_x/_y/_z)
    tension_end@element=1,end=1  axial force at the first end of element 1
    load_factor                  a record variable without an index
Without --series: the largest end tension over the elements and the displacement magnitude of
the node that moves most. Units and names come from the file's CF attributes; the title names
the case. Records of static steps (which share a time) are drawn as points.
"""
import argparse
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402


def parse_spec(spec):
    name, _, index = spec.partition("@")
    selection = {}
    for part in filter(None, index.split(",")):
        key, _, value = part.partition("=")
        selection[key.strip()] = int(value)
    return name.strip(), selection


def select(ds, name, selection):
    """The series of `name` at `selection`, its label and its units."""
    where = {}
    for key, value in selection.items():
        if key == "end":
            where[key] = value - 1  # 'end' has no coordinate: 1 = first, 2 = last
        elif key in ds.indexes:
            where[key] = value
        else:
            raise SystemExit("flexmoor plot: unknown index '%s' in %s" % (key, name))
    positional = {k: v for k, v in where.items() if k == "end"}
    labelled = {k: v for k, v in where.items() if k != "end"}
    if name == "speed":
        parts = [ds["velocity" + a].sel(labelled) for a in ("_x", "_y", "_z")]
        values = np.sqrt(sum(p ** 2 for p in parts))
        units = ds["velocity_x"].attrs.get("units", "")
        long_name = "speed"
    elif name in ds:
        values = ds[name].sel(labelled).isel(positional)
        units = ds[name].attrs.get("units", "")
        long_name = ds[name].attrs.get("long_name", name)
    else:
        raise SystemExit("flexmoor plot: no variable '%s' in the file" % name)
    if set(values.dims) - {"time"}:
        raise SystemExit("flexmoor plot: %s needs an index for %s" %
                         (name, ", ".join(sorted(set(values.dims) - {"time"}))))
    where_text = ", ".join("%s %d" % kv for kv in selection.items())
    label = long_name + (" (" + where_text + ")" if where_text else "")
    return values, label, units


def default_specs(ds):
    specs = []
    if "tension_end" in ds:
        specs.append(("max_tension", {}))
    moved = np.sqrt(ds.displacement_x ** 2 + ds.displacement_y ** 2 + ds.displacement_z ** 2)
    node = int(moved.max("time").argmax())
    specs.append(("displacement_magnitude", {"node": int(ds.node[node])}))
    return specs


def default_series(ds, name, selection):
    if name == "max_tension":
        return (ds.tension_end.max(("element", "end")), "largest end tension over the elements",
                ds.tension_end.attrs.get("units", ""))
    node = selection["node"]
    parts = [ds["displacement" + a].sel(node=node) for a in ("_x", "_y", "_z")]
    return (np.sqrt(sum(p ** 2 for p in parts)), "displacement magnitude (node %d)" % node,
            ds.displacement_x.attrs.get("units", ""))


def main(argv):
    parser = argparse.ArgumentParser(prog="flexmoor plot", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="a flexmoor netCDF result (DIR/<case>.nc)")
    parser.add_argument("-o", "--output", required=True, help="the PNG to write")
    parser.add_argument("--series", action="append", default=[], metavar="SPEC")
    parser.add_argument("--title", help="the figure's title (default: the case's title)")
    args = parser.parse_args(argv)

    ds = xr.open_dataset(args.result)
    specs = [parse_spec(s) for s in args.series]
    panels, short_names = [], []
    for name, selection in specs or default_specs(ds):
        short_names.append(name.replace("_", " "))
        if specs:
            panels.append(select(ds, name, selection))
        else:
            panels.append(default_series(ds, name, selection))

    time_units = ds.time.attrs.get("units", "s")
    figure, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                figsize=(8.0, 2.2 + 1.9 * len(panels)), constrained_layout=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    dynamic = np.concatenate([[False], np.diff(ds.time.values) > 0])
    for k, ((values, label, units), short) in enumerate(zip(panels, short_names)):
        ax = axes[k][0]
        t, y = ds.time.values, np.asarray(values)
        colour = colours[k % len(colours)]
        line = dynamic | np.roll(dynamic, -1)
        ax.plot(t[line], y[line], color=colour, linewidth=1.4, label=textwrap.fill(label, 60))
        if (~dynamic).any():
            ax.plot(t[~dynamic], y[~dynamic], "o", color=colour, markersize=3.5,
                    label="end of a static step" if k == 0 else None)
        ax.set_ylabel("%s [%s]" % (short, units) if units else short)
        ax.ticklabel_format(axis="y", useOffset=False)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small", frameon=False)
    axes[-1][0].set_xlabel("time [%s]" % time_units)
    title = args.title or ds.attrs.get("title", ds.attrs.get("case_name", ""))
    figure.suptitle(title, fontsize="medium")
    figure.savefig(args.output, dpi=130)
    print("flexmoor plot: wrote %s (%d panels)" % (args.output, len(panels)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
