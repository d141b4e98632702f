"""flexmoor plot --mooring: the figure of a mooring. Above, when the run has time records, the
fairlead tension of every line with an anchor over time; below, each line's profile in its own
vertical plane (horizontal distance from its anchor against z) at the run's last state, with
thin lines at a few earlier records of the time axis, the seabed under the line (the file's
seabed_z) and the water line (z = 0)."""
import numpy as np

from plot_common import fail, in_force_units, pyplot

PROFILES_OVER_TIME = 8  # earlier records drawn thin under the last state


def anchored_lines(ds):
    """(name, nodes from anchor to fairlead as indices into `node`, (element index, end index) of
    the fairlead's end) of each line with an anchor (line_anchor 1: at its start, 2: at its
    end)."""
    for needed in ("line_anchor", "node_line", "node_arc_length", "element_line"):
        if needed not in ds:
            fail("--mooring: the file has no %s (a case without named lines)" % needed)
    node_line = ds.node_line.values
    arc = ds.node_arc_length.values
    element_line = ds.element_line.values
    index = {int(n): i for i, n in enumerate(ds.node.values)}
    counts = ds.element_node_count.values
    element_nodes = ds.element_nodes.values
    ends, at = [], 0
    for count in counts:
        own = element_nodes[at:at + count]
        at += count
        ends.append((index[int(own[0])], index[int(own[-1])]))
    found = []
    for k, (name, anchor) in enumerate(zip(ds.line_name.values, ds.line_anchor.values), 1):
        if int(anchor) == 0:
            continue
        own = np.flatnonzero(node_line == k)
        order = own[np.argsort(arc[own])]
        if int(anchor) == 2:
            order = order[::-1]
        fairlead = int(order[-1])
        end = next(((e, ends[e].index(fairlead)) for e in np.flatnonzero(element_line == k)
                    if fairlead in ends[e]), None)
        found.append((str(name), order, end))
    if not found:
        fail("--mooring: the file has no line with an anchor (line_anchor is 0 for every line)")
    return found


def last_state(ds, name):
    """`name` (a node variable) at the run's last state: the last time record, or the last stage
    record when the run has no time records."""
    if ds.sizes.get("time", 0) > 0:
        return ds[name].isel(time=-1).values
    return ds["stage_" + name].isel(stage=-1).values


def draw_tensions(ax, ds, lines, colours):
    raw = np.stack([ds.tension_end.isel(element=e, end=j).values for _, _, (e, j) in lines])
    values, units = in_force_units(raw, ds.tension_end.attrs.get("units", ""))
    for (name, _, _), y, colour in zip(lines, values, colours):
        ax.plot(ds.time.values, y, color=colour, linewidth=1.3, label="%s, fairlead" % name)
    ax.set_xlabel("time [%s]" % ds.time.attrs.get("units", "s"))
    ax.set_ylabel("fairlead tension [%s]" % units)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False)


def draw_profiles(ax, ds, lines, colours):
    x, y, z = (last_state(ds, "position_" + a) for a in "xyz")
    records = ds.sizes.get("time", 0)
    earlier = np.unique(np.linspace(0, records - 1, PROFILES_OVER_TIME + 1).astype(int))[:-1] \
        if records > 1 else []
    profiles = []
    for (name, order, _), colour in zip(lines, colours):
        anchor = order[0]
        distance = np.hypot(x[order] - x[anchor], y[order] - y[anchor])
        profiles.append((order, distance))
        for r in earlier:
            xe, ye, ze = (ds["position_" + a].isel(time=int(r)).values for a in "xyz")
            ax.plot(np.hypot(xe[order] - xe[anchor], ye[order] - ye[anchor]), ze[order],
                    color=colour, linewidth=0.6, alpha=0.35)
        ax.plot(distance, z[order], color=colour, linewidth=1.6, marker="o", markersize=2.0,
                label=name)
    if "seabed_z" in ds:  # under each line, as it passes over the bed
        depth = np.ptp(z) + 1e-9
        for k, (order, distance) in enumerate(profiles):
            bed = ds.seabed_z.values[order]
            ax.fill_between(distance, bed, np.min(bed) - 0.04 * depth, color="#b39b77",
                            alpha=0.35, linewidth=0, label="seabed" if k == 0 else None)
            ax.plot(distance, bed, color="#8a6d3b", linewidth=1.0)
    if "seabed_z" in ds:
        ax.axhline(0.0, color="#3b78b0", linewidth=1.0, linestyle="--", label="water line")
    units = ds.position_z.attrs.get("units", "")
    ax.set_xlabel("horizontal distance from the anchor [%s]" % units)
    ax.set_ylabel("z [%s]" % units)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False)


def draw_mooring(ds, args):
    if "position_x" not in ds and "stage_position_x" not in ds:
        fail("--mooring: the file has no position_x (the case's output: fields: leaves out "
             "position)")
    lines = anchored_lines(ds)
    dynamic = ds.sizes.get("time", 0) > 1 and "tension_end" in ds and \
        all(end is not None for _, _, end in lines)
    plt = pyplot()
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colours = [colours[k % len(colours)] for k in range(len(lines))]
    figure, axes = plt.subplots(2 if dynamic else 1, 1, squeeze=False,
                                figsize=(8.5, 8.0 if dynamic else 4.8), constrained_layout=True)
    if dynamic:
        draw_tensions(axes[0][0], ds, lines, colours)
    draw_profiles(axes[-1][0], ds, lines, colours)
    return figure, "%d lines" % len(lines)
