"""flexmoor plot: figures (PNG) of a flexmoor run or study, drawn with matplotlib (the study
figures in study_figures.py, the helpers both use in plot_common.py).

Of a run's netCDF (DIR/<case>.nc), one figure kind at a time:
    --series SPEC ...        time series, one panel a SPEC (the default: the largest end tension
                             and the displacement of the node that moves most)
    --spectrum SPEC          Welch spectrum (Hann window, half overlap) of one series, against
                             the target spectrum of the run's sea (its sea_spectrum_* attributes)
    --shapes T1,T2,...       the deformed lines at the records nearest those times (a plane)
    --mooring                every anchored line's fairlead tension over time and the lines'
                             profiles over the seabed and under the water line
Of a study's DIR/study.nc:
    --rao NAME --against P   NAME_amplitude against the parameter P (RAO with --wave-height)
    --extremes NAME --against P [--group Q]
                             NAME_max and NAME_mpm against P, one colour per value of Q, the
                             mean over Q's values as lines
    --psd NAME               the members' response spectra NAME_psd over `frequency`
SPEC is VARIABLE@INDEX, for example
    position_x@node=5            x of node 5 (1-based, as in the file's `node` coordinate)
    speed@node=5                 |velocity| of node 5 (derived from velocity_x/_y/_z)
    tension_end@element=1,end=1  axial force at the first end of element 1 (end=1 or end=first:
                                 the element's first node, end=2 or end=last: its last, as the
                                 file's `end` coordinate says)
    wave_elevation               a record variable without an index
A series is drawn from the records of the time axis (the dynamic steps') as a line, with the
states that close the other steps (the `stage` records, at their stage_time) as dots.
Units and names come from the files' CF attributes. Bad arguments (a variable the file does
not hold among them): a message naming what is wrong, exit code 2. A figure that cannot be
written, a Python module missing or any other failure: a one-line message, exit code 4; never a
traceback. The directory of -o is created when it does not exist.
"""
import argparse
import errno
import os
import sys
import textwrap

from plot_common import (FAILED, energy_top, fail, in_force_units, missing_module, number_text,
                         plain_ticks, pyplot)

try:
    import numpy as np
    import xarray as xr
except ImportError as e:
    missing_module(e)

from mooring_figure import draw_mooring
from study_figures import draw_extremes, draw_psd, draw_rao


# --------------------------------------------------------------------------------------------
# Series of a run
# --------------------------------------------------------------------------------------------

END_WORDS = {"first": 1, "last": 2}


def parse_spec(spec):
    name, _, index = spec.partition("@")
    selection = {}
    for part in filter(None, index.split(",")):
        key, _, value = part.partition("=")
        key, value = key.strip(), value.strip()
        if key == "end" and value in END_WORDS:
            selection[key] = END_WORDS[value]
            continue
        try:
            selection[key] = int(value)
        except ValueError:
            fail("the index '%s' of %s is not a whole number (expected KEY=N, like node=5%s)"
                 % (part, spec, ", or end=first or end=last" if key == "end" else ""))
    return name.strip(), selection


def record_variable(ds, name, stage):
    """The variable `name` of the time records, or of the stage records (stage_NAME)."""
    return ds["stage_" + name] if stage else ds[name]


def has_records(ds, name, stage):
    return ("stage_" + name if stage else name) in ds


def select(ds, name, selection, stage=False):
    """The series of `name` at `selection` (of the stage records when `stage`), its label and its
    units; None for the stage records when the file has none of that variable."""
    labelled, positional = {}, {}
    for key, value in selection.items():
        if key == "end" and value not in (1, 2):
            fail("end=%d in %s: expected end=1 (first) or end=2 (last)" % (value, name))
        if key in ds.indexes:
            if value not in ds.indexes[key]:
                fail("%s=%d in %s: no such %s in the file (it has %d to %d)" %
                     (key, value, name, key, ds.indexes[key].min(), ds.indexes[key].max()))
            labelled[key] = value
        elif key in ds.dims:  # a dimension without a coordinate: 1-based position
            positional[key] = value - 1
        else:
            fail("unknown index '%s' in %s" % (key, name))
    if name == "speed":
        components = ["velocity" + a for a in ("_x", "_y", "_z")]
        absent = [c for c in components if c not in ds]
        if absent:
            fail("speed is |velocity| and needs velocity_x, _y and _z; the file does not hold "
                 "%s (the case's output: fields: leaves out velocity)" % ", ".join(absent))
    elif name not in ds:
        fail("no variable '%s' in the file (its series: %s)" % (name, record_variables(ds)))
    source = "velocity_x" if name == "speed" else name
    require_indices(ds[source], name, selection)
    if stage and not has_records(ds, source, True):
        return None
    if name == "speed":
        parts = [record_variable(ds, "velocity" + a, stage).sel(labelled).isel(positional)
                 for a in ("_x", "_y", "_z")]
        values = np.sqrt(sum(p ** 2 for p in parts))
        units = ds["velocity_x"].attrs.get("units", "")
        long_name = "speed"
    else:
        values = record_variable(ds, name, stage).sel(labelled).isel(positional)
        units = ds[name].attrs.get("units", "")
        long_name = ds[name].attrs.get("long_name", name)
    extra = set(values.dims) - {"time", "stage"}
    if extra:
        fail("%s needs an index for %s" % (name, ", ".join(sorted(extra))))
    where_text = ", ".join("%s %d" % kv for kv in selection.items())
    label = long_name + (" (" + where_text + ")" if where_text else "")
    return values, label, units


def require_indices(variable, name, where):
    """Every index of a SPEC must be a dimension of its variable."""
    extra = sorted(set(where) - set(variable.dims))
    if extra:
        fail("%s has no %s index (its dimensions: %s)" %
             (name, " or ".join(extra), ", ".join(variable.dims)))


def record_variables(ds):
    """The variables over time that the file holds, for a message; "none" when there are none."""
    names = sorted(n for n in ds.data_vars if "time" in ds[n].dims)
    return ", ".join(names) or "none"


def default_specs(ds):
    """The default figure's panels, those the file can give: the largest end tension (needs
    tension_end) and the displacement of the node that moves most (displacement_x, _y, _z)."""
    specs = []
    if "tension_end" in ds:
        specs.append(("max_tension", {}))
    displacement = ["displacement" + a for a in ("_x", "_y", "_z")]
    stage = ds.sizes.get("time", 0) == 0
    if all(has_records(ds, d, stage) for d in displacement):
        moved = np.sqrt(sum(record_variable(ds, d, stage) ** 2 for d in displacement))
        node = int(moved.max("stage" if stage else "time").argmax())
        specs.append(("displacement_magnitude", {"node": int(ds.node[node])}))
    left_out = [what for what, present in (
        ("the largest end tension (no tension_end)", "tension_end" in ds),
        ("the displacement of the node that moves most (no displacement_x, _y, _z)",
         all(d in ds for d in displacement))) if not present]
    if not specs:
        fail("the default figure draws the largest end tension and the displacement of the node "
             "that moves most, and the file has neither tension_end nor displacement_x, _y, _z "
             "(the case's output: fields: leaves out tension and displacement); choose series "
             "with --series VARIABLE@node=N (the file's: %s)" % record_variables(ds))
    for what in left_out:
        print("flexmoor plot: the default figure leaves out %s: the case's output: fields: did "
              "not write it" % what, file=sys.stderr)
    return specs


def default_series(ds, name, selection, stage=False):
    needed = "tension_end" if name == "max_tension" else "displacement_x"
    if stage and not has_records(ds, needed, True):
        return None
    if name == "max_tension":
        return (record_variable(ds, "tension_end", stage).max(("element", "end")),
                "largest end tension over the elements", ds.tension_end.attrs.get("units", ""))
    node = selection["node"]
    parts = [record_variable(ds, "displacement" + a, stage).sel(node=node)
             for a in ("_x", "_y", "_z")]
    return (np.sqrt(sum(p ** 2 for p in parts)), "displacement magnitude (node %d)" % node,
            ds.displacement_x.attrs.get("units", ""))


def draw_series(ds, args):
    if ds.sizes.get("time", 0) == 0:
        fail("%s holds no records (no time)" % args.result)
    specs = [parse_spec(s) for s in args.series]
    panels, stages, short_names = [], [], []
    for name, selection in specs or default_specs(ds):
        short_names.append(name.replace("_", " "))
        if specs:
            panels.append(select(ds, name, selection))
            stages.append(select(ds, name, selection, stage=True))
        else:
            panels.append(default_series(ds, name, selection))
            stages.append(default_series(ds, name, selection, stage=True))

    time_units = ds.time.attrs.get("units", "s")
    plt = pyplot()
    figure, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False,
                                figsize=(8.0, 2.2 + 1.9 * len(panels)), constrained_layout=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, ((values, label, units), stage, short) in enumerate(zip(panels, stages, short_names)):
        ax = axes[k][0]
        raw = np.asarray(values, dtype=float)
        largest = np.abs(raw[np.isfinite(raw)]).max() if np.isfinite(raw).any() else 0.0
        y, shown_units = in_force_units(raw, units, largest)
        colour = colours[k % len(colours)]
        ax.plot(ds.time.values, y, color=colour, linewidth=1.4, label=textwrap.fill(label, 60))
        if stage is not None and ds.sizes.get("stage", 0) > 0:
            stage_y, _ = in_force_units(np.asarray(stage[0], dtype=float), units, largest)
            ax.plot(ds.stage_time.values, stage_y, "o", color=colour, markersize=3.5,
                    label="state closing a step that is not dynamic" if k == 0 else None)
        ax.set_ylabel("%s [%s]" % (short, shown_units) if shown_units else short)
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small", frameon=False)
    axes[-1][0].set_xlabel("time [%s]" % time_units)
    return figure, "%d panel%s" % (len(panels), "" if len(panels) == 1 else "s")


# --------------------------------------------------------------------------------------------
# Spectrum of a run's series against the sea's target
# --------------------------------------------------------------------------------------------

def welch(x, dt, segment):
    """libhydro/signal/welch.hpp's estimate: segments of `segment` (even) samples, each less its
    mean under the Hann window sin^2(pi j / L), overlapping by half; one-sided density per
    circular frequency S(omega_k) = 2 |X_k|^2 dt / (2 pi sum w^2) (the factor 2 not at k = 0 and
    L / 2) at omega_k = 2 pi k / (L dt). Returns omega, S and the number of segments."""
    window = np.sin(np.pi * np.arange(segment) / segment) ** 2
    power = np.zeros(segment // 2 + 1)
    starts = range(0, len(x) - segment + 1, segment // 2)
    for start in starts:
        piece = x[start:start + segment]
        power += np.abs(np.fft.rfft((piece - piece.mean()) * window)) ** 2
    one_sided = np.full(power.size, 2.0)
    one_sided[[0, -1]] = 1.0
    density = power * one_sided * dt / (2.0 * np.pi * np.sum(window ** 2) * len(starts))
    return 2.0 * np.pi * np.arange(power.size) / (segment * dt), density, len(starts)


def simpson(f, a, b, n):
    x = np.linspace(a, b, n + 1)
    weights = np.ones(n + 1)
    weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
    return np.sum(weights * f(x)) * (b - a) / n / 3.0


def jonswap_density(omega, hs, tp, gamma):
    """libhydro/waves/wave_spectrum.hpp's JONSWAP (gamma 1: Pierson-Moskowitz), S per circular
    frequency: 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w / wp)^-4) gamma^exp(-(w - wp)^2 / (2 sigma^2
    wp^2)), sigma 0.07 at w <= wp and 0.09 above, scaled so that m0 = Hs^2 / 16 with m0 computed
    as libhydro computes it (Simpson, 20,000 intervals over [0.3, 2] wp and over [2, 60] wp, the
    w^-5 tail beyond added analytically)."""
    wp = 2.0 * np.pi / tp

    def shape(w):
        w = np.asarray(w, dtype=float)
        safe = np.where(w > 0.0, w, 1.0)
        pm = (5.0 / 16.0 * hs * hs * wp ** 4 * safe ** -5.0 * np.exp(-1.25 * (safe / wp) ** -4.0))
        if gamma != 1.0:
            sigma = np.where(safe <= wp, 0.07, 0.09)
            pm = pm * gamma ** np.exp(-0.5 * ((safe - wp) / (sigma * wp)) ** 2)
        return np.where(w > 0.0, pm, 0.0)

    a, b = 0.3 * wp, 60.0 * wp
    m0 = simpson(shape, a, 2.0 * wp, 20000) + simpson(shape, 2.0 * wp, b, 20000)
    m0 += shape(b) * b / 4.0
    return (hs * hs / 16.0 / m0) * shape(omega)


def target_spectrum(attrs, length_units, time_units):
    """The run's target spectrum as a function of omega and a label, or None."""
    kind = attrs.get("sea_spectrum")
    if kind == "table":
        omega = np.atleast_1d(attrs["sea_spectrum_omega"])
        density = np.atleast_1d(attrs["sea_spectrum_density"])
        return (lambda w: np.interp(w, omega, density, left=0.0, right=0.0)), "target: table"
    if kind in ("jonswap", "pierson_moskowitz"):
        hs, tp = float(attrs["sea_spectrum_Hs"]), float(attrs["sea_spectrum_Tp"])
        gamma = float(attrs["sea_spectrum_gamma"])
        name = "JONSWAP" if kind == "jonswap" else "Pierson-Moskowitz"
        label = "target: %s, Hs %s %s, Tp %s %s" % (name, number_text(hs), length_units,
                                                    number_text(tp), time_units)
        if kind == "jonswap":
            label += ", gamma %s" % number_text(gamma)
        return (lambda w: jonswap_density(w, hs, tp, gamma)), label
    return None


def last_dynamic_record(ds, values, start):
    """The series over the run's last step (a dynamic one), from time `start` on, evenly sampled:
    the records of a step that cut its time step short are interpolated linearly onto the
    step's own (largest) time step. Returns the samples and their time step."""
    steps = ds.step_number.values
    chosen = steps == steps[-1]
    if start is not None:
        chosen &= ds.time.values >= start
    t = ds.time.values[chosen]
    if t.size < 8 or not np.all(np.diff(t) > 0):
        fail("the spectrum needs the records of a dynamic last step, 8 or more (got %d records "
             "of step %d%s)" % (t.size, steps[-1], "" if start is None else " from t = %g" % start))
    x = np.asarray(values)[chosen]
    dt = float(np.max(np.diff(t)))
    if np.ptp(np.diff(t)) > 1e-9 * dt:
        even = t[0] + dt * np.arange(int(np.floor((t[-1] - t[0]) / dt + 1e-9)) + 1)
        print("flexmoor plot: the last step's records are not evenly spaced (dt %g to %g): "
              "interpolated onto dt = %g" % (np.diff(t).min(), np.diff(t).max(), dt),
              file=sys.stderr)
        x = np.interp(even, t, x)
    return x, dt


def draw_spectrum(ds, args):
    name, selection = parse_spec(args.spectrum)
    values, label, units = select(ds, name, selection)
    if ds.sizes["time"] == 0:
        fail("the spectrum needs the records of a dynamic step; the file has none (only the "
             "states closing its other steps, `stage`)")
    x, dt = last_dynamic_record(ds, values, args.start)
    x, units = in_force_units(x, units)
    time_units = ds.time.attrs.get("units", "s")
    duration = x.size * dt
    segment_time = args.segment if args.segment is not None else duration / 4.0
    segment = 2 * int(round(segment_time / dt / 2.0))
    if segment < 8 or segment > x.size:
        fail("--segment %g: expected at least 8 samples and at most the record's %g %s "
             "(got %d samples of %g %s)" % (segment_time, duration, time_units, segment, dt,
                                            time_units))
    omega, density, segments = welch(x, dt, segment)
    spectral_units = "%s2 %s rad-1" % (units, time_units) if units else "%s rad-1" % time_units
    plt = pyplot()
    figure, ax = plt.subplots(figsize=(8.0, 4.8), constrained_layout=True)
    m0 = np.sum(density) * (omega[1] - omega[0])
    estimate = "%s: Welch, %d segments of %g %s (4 sqrt(m0) = %s %s)" % (
        label, segments, segment * dt, time_units, number_text(4.0 * np.sqrt(m0)), units)
    ax.plot(omega, density, color="C0", linewidth=1.3, label=textwrap.fill(estimate, 70))
    length_units = ds["position_x"].attrs.get("units", "m") if "position_x" in ds else "m"
    target = target_spectrum(ds.attrs, length_units, time_units)
    # The frequency axis ends where the energy is (99.9% of it, and a margin): the estimate's
    # or the target's within the synthesised band, whichever is further.
    top = energy_top(omega, density)
    if target is not None:
        function, target_label = target
        w = np.linspace(omega[1] * 0.5, omega[-1], 2000)
        band = np.atleast_1d(ds.attrs.get("sea_spectrum_band", [0.0, omega[-1]]))
        sea = w[w <= band[-1]]
        if sea.size > 1:
            top = max(top, energy_top(sea, function(sea)))
        if units == length_units:  # an elevation or a motion: on the estimate's axis
            twin = ax
        else:  # another quantity, all its frequencies: the target on its own axis at the right
            twin = ax.twinx()
            twin.set_ylabel("target wave spectrum [%s2 %s rad-1]" % (length_units, time_units))
        twin.plot(w, function(w), color="C3", linewidth=1.6, linestyle="--",
                  label="%s (%s2 %s rad-1)" % (target_label, length_units, time_units))
        twin.axvspan(band[0], band[-1], color="C3", alpha=0.06,
                     label="synthesised band %.3g to %.3g rad/s" % (band[0], band[-1]))
        twin.set_ylim(bottom=0.0)
        if twin is not ax:
            handles, labels = ax.get_legend_handles_labels()
            more, more_labels = twin.get_legend_handles_labels()
            ax.legend(handles + more, labels + more_labels, loc="upper right", fontsize="small",
                      frameon=False)
    else:
        print("flexmoor plot: the file states no target spectrum (no sea_spectrum attribute): "
              "the estimate alone", file=sys.stderr)
    if target is None or twin is ax:
        ax.legend(loc="upper right", fontsize="small", frameon=False)
    ax.set_xlim(0.0, top)
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("circular frequency omega [rad/s]")
    ax.set_ylabel("spectral density [%s]" % spectral_units)
    ax.grid(True, alpha=0.3)
    return figure, "spectrum of %d samples, %d segments" % (x.size, segments)


# --------------------------------------------------------------------------------------------
# Line shapes of a run
# --------------------------------------------------------------------------------------------

def parse_times(text):
    try:
        times = [float(t) for t in text.split(",") if t.strip()]
    except ValueError:
        fail("--shapes %s: expected times separated by commas, like 100,200" % text)
    if not times:
        fail("--shapes needs at least one time, like --shapes 100,200")
    return times


def element_polylines(ds):
    """Each element's nodes (indices into `node`) in drawing order: lines along their nodes,
    membranes closed over their corners; single-node elements left out."""
    counts = ds.element_node_count.values
    nodes = ds.element_nodes.values
    index = {int(n): i for i, n in enumerate(ds.node.values)}
    types = [str(t) for t in ds.element_type.values] if "element_type" in ds else [""] * len(counts)
    polylines, at = [], 0
    for count, kind in zip(counts, types):
        own = [index[int(n)] for n in nodes[at:at + count]]
        at += count
        if count < 2:
            continue
        if kind.startswith("membrane"):
            corners = own[:3] if count in (3, 6) else own[:4]
            own = corners + corners[:1]
        polylines.append(own)
    return polylines


def draw_shapes(ds, args):
    times = parse_times(args.shapes)
    plane = args.plane
    if len(plane) != 2 or any(a not in "xyz" for a in plane) or plane[0] == plane[1]:
        fail("--plane %s: expected two of x, y, z, like xz" % plane)
    if "position_x" not in ds:
        fail("--shapes: the file has no position_x (the case's output: fields: leaves out "
             "position)")
    # Every record, the stage records (steps that are not dynamic) first: at a time both have,
    # the later record in the run is drawn.
    records = [(float(t), True, i) for i, t in enumerate(ds.stage_time.values)]
    records += [(float(t), False, i) for i, t in enumerate(ds.time.values)]
    records.sort(key=lambda r: r[0])
    t = np.array([r[0] for r in records])
    if t.size == 0:
        fail("--shapes: the file has no records")
    time_units = ds.time.attrs.get("units", "s")
    spacing = np.min(np.diff(t)[np.diff(t) > 0]) if np.any(np.diff(t) > 0) else 0.0
    chosen = []
    for time in times:
        if time < t.min() - spacing or time > t.max() + spacing:
            fail("--shapes: the time %g %s is outside the records (%g to %g %s)" %
                 (time, time_units, t.min(), t.max(), time_units))
        nearest = np.abs(t - time)
        chosen.append(records[int(np.flatnonzero(nearest == nearest.min())[-1])])
    polylines = element_polylines(ds)
    units = ds["position_x"].attrs.get("units", "")
    plt = pyplot()
    from matplotlib.collections import LineCollection

    figure, ax = plt.subplots(figsize=(9.0, 5.5), constrained_layout=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(times)))
    for (time, stage, record), colour in zip(chosen, colours):
        dim = "stage" if stage else "time"
        u = record_variable(ds, "position_" + plane[0], stage).isel({dim: record}).values
        v = record_variable(ds, "position_" + plane[1], stage).isel({dim: record}).values
        segments = [np.column_stack([u[p], v[p]]) for p in polylines]
        names = ds.stage_step if stage else ds.step_name
        label = "t = %g %s (%s)" % (time, time_units, str(names.values[record]))
        ax.add_collection(LineCollection(segments, colors=[colour], linewidths=1.4, label=label))
        ax.plot(u, v, "o", color=colour, markersize=2.0)
    ax.autoscale()
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("%s [%s]" % (plane[0], units))
    ax.set_ylabel("%s [%s]" % (plane[1], units))
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False)
    return figure, "%d shapes" % len(times)


# --------------------------------------------------------------------------------------------

RUN_KINDS = {"series": draw_series, "spectrum": draw_spectrum, "shapes": draw_shapes,
             "mooring": draw_mooring}
STUDY_KINDS = {"rao": draw_rao, "extremes": draw_extremes, "psd": draw_psd}


class Parser(argparse.ArgumentParser):
    def error(self, message):
        fail(message)


def main(argv):
    parser = Parser(prog="flexmoor plot", description=__doc__,
                    formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="a run's DIR/<case>.nc or a study's DIR/study.nc")
    parser.add_argument("-o", "--output", required=True, help="the PNG to write")
    kinds = parser.add_mutually_exclusive_group()
    kinds.add_argument("--series", action="append", default=[], metavar="SPEC")
    kinds.add_argument("--spectrum", metavar="SPEC")
    kinds.add_argument("--shapes", metavar="T1,T2,...")
    kinds.add_argument("--mooring", action="store_const", const=True, default=None)
    kinds.add_argument("--rao", metavar="NAME")
    kinds.add_argument("--extremes", metavar="NAME")
    kinds.add_argument("--psd", metavar="NAME")
    parser.add_argument("--segment", type=float, help="--spectrum: Welch segment, time units")
    parser.add_argument("--from", dest="start", type=float,
                        help="--spectrum: leave out the records before this time")
    parser.add_argument("--plane", default="xz", help="--shapes: the plane drawn (xz)")
    parser.add_argument("--against", metavar="PARAMETER")
    parser.add_argument("--group", metavar="PARAMETER")
    parser.add_argument("--wave-height", metavar="H|PARAMETER")
    parser.add_argument("--title", help="the figure's title (default: the file's title)")
    args = parser.parse_args(argv)

    kind = next((k for k in ("spectrum", "shapes", "mooring", "rao", "extremes", "psd")
                 if getattr(args, k) is not None), "series")
    used = {"segment": "spectrum", "start": "spectrum", "wave_height": "rao",
            "group": "rao extremes", "against": "rao extremes"}
    for option, owners in used.items():
        if getattr(args, option) is not None and kind not in owners.split():
            fail("--%s is an option of %s, not of --%s" % (
                option.replace("_", "-").replace("start", "from"),
                " and ".join("--" + o for o in owners.split()), kind))
    if os.path.isdir(args.output):
        fail("-o %s is a directory (expected the PNG file to write, like %s)"
             % (args.output, os.path.join(args.output, "figure.png")))
    try:
        ds = xr.open_dataset(args.result)
    except (OSError, ValueError) as e:
        fail("cannot read %s as netCDF (%s)" % (args.result, e))
    study = "member" in ds.dims
    if kind in STUDY_KINDS and not study:
        fail("--%s draws a study's DIR/study.nc; %s has no 'member' dimension (a run's "
             "netCDF takes --series, --spectrum, --shapes or --mooring)" % (kind, args.result))
    if kind in RUN_KINDS and study:
        fail("%s is a study (a 'member' dimension): it takes --rao, --extremes or --psd"
             % args.result)
    figure, what = (STUDY_KINDS if study else RUN_KINDS)[kind](ds, args)
    title = args.title or ds.attrs.get("title", ds.attrs.get("case_name", ""))
    figure.suptitle(title, fontsize="medium")
    plain_ticks(figure)
    output_directory(args.output)
    try:
        figure.savefig(args.output, dpi=130)
    except OSError as e:
        fail("cannot write %s (%s)" % (args.output, e.strerror or e), FAILED)
    print("flexmoor plot: wrote %s (%s)" % (args.output, what))
    return 0


def output_directory(png):
    """The directory of -o, created when it does not exist."""
    directory = os.path.dirname(png)
    if directory and not os.path.isdir(directory):
        try:
            os.makedirs(directory)
        except OSError as e:
            reason = ("a file of that name is in the way" if e.errno in (errno.EEXIST,
                                                                          errno.ENOTDIR)
                      else e.strerror or str(e))
            fail("-o %s: cannot create the directory %s (%s)" % (png, directory, reason), FAILED)


def guarded(argv):
    """main, with any failure it did not foresee as one line and exit code 4 (not a traceback)."""
    try:
        return main(argv)
    except MemoryError:
        fail("out of memory", FAILED)
    except Exception as e:  # SystemExit (fail, --help) and KeyboardInterrupt pass
        text = " ".join(str(e).split()) or "no message"
        fail("internal error, the figure was not drawn (%s: %s)" % (type(e).__name__, text),
             FAILED)


if __name__ == "__main__":
    sys.exit(guarded(sys.argv[1:]))
