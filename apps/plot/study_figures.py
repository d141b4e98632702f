"""Figures of a study's DIR/study.nc for `flexmoor plot` (flexmoor_plot.py): a response-
amplitude curve (--rao), extremes against a parameter (--extremes) and the members' response
spectra (--psd), from the variables study_format.md names."""
import textwrap

import numpy as np

from plot_common import energy_top, fail, in_force_units, number_text, pyplot, value_text


def study_parameters(ds):
    return ds.attrs.get("study_parameters", "").split()


def require_parameter(ds, name, option):
    if name is None:
        fail("%s needs --against PARAMETER (the study's: %s)" %
             (option, ", ".join(study_parameters(ds)) or "none"))
    if name not in ds or "member" not in ds[name].dims:
        fail("no parameter '%s' in the study (its parameters: %s)" %
             (name, ", ".join(study_parameters(ds)) or "none"))
    if not np.issubdtype(ds[name].dtype, np.number):
        fail("%s --against %s: a text parameter cannot be an axis (use it as --group)"
             % (option, name))
    return ds[name]


def require_statistic(ds, name, statistic):
    variable = "%s_%s" % (name, statistic)
    if variable not in ds:
        collected = ds.attrs.get("collect", "")
        fail("no variable '%s' in the study (collected: %s; statistics are NAME_max, _min, "
             "_mean, _std, _amplitude, _mpm, _psd)" % (variable, collected or "nothing"))
    return ds[variable]


def axis_label(variable, fallback, units=None):
    """'NAME [UNITS]' of a variable, its own units unless `units` is given."""
    name = variable.attrs.get("long_name", variable.attrs.get("flexmoor_path", fallback))
    units = variable.attrs.get("units", "") if units is None else units
    return "%s [%s]" % (name, units) if units else name


def unit_suffix(units):
    """' m' after a value; nothing for a pure number (a seed or a count: units "1")."""
    return " " + units if units and units != "1" else ""


def parameter_text(ds, member):
    """'Hs 4 m, seed 2' for one member: its varied parameters."""
    parts = []
    for p in study_parameters(ds):
        value = value_text(ds[p].values[member])
        units = ds[p].attrs.get("units", "")
        parts.append("%s %s%s" % (ds[p].attrs.get("flexmoor_path", p).split(".")[-1], value,
                                  unit_suffix(units)))
    return ", ".join(parts)


def complete(ds):
    if "status" in ds:
        return np.asarray(ds.status.values) == 0
    return np.ones(ds.sizes["member"], dtype=bool)


def length_units(ds):
    """The study's length unit: the first of its unit_system, "US (ft, slug, s, lbf)" (m for a
    file that does not say)."""
    system = ds.attrs.get("unit_system", "")
    inside = system.partition("(")[2].partition(")")[0]
    return inside.split(",")[0].strip() or "m"


def wave_amplitude(ds, text):
    """Half the wave height: a parameter's values per member, or a number for all (in the
    study's length unit)."""
    if text in ds and "member" in ds[text].dims:
        return (0.5 * np.asarray(ds[text].values, dtype=float),
                ds[text].attrs.get("units", length_units(ds)))
    try:
        height = float(text)
    except ValueError:
        fail("--wave-height %s: expected a height (a number, in the study's length unit) or a "
             "parameter (the study's: %s)" % (text, ", ".join(study_parameters(ds)) or "none"))
    if not height > 0.0:
        fail("--wave-height %s: expected a height > 0" % text)
    return np.full(ds.sizes["member"], 0.5 * height), length_units(ds)


def groups_of(ds, group, option):
    """Member masks per value of the --group parameter (one group of all without it)."""
    if group is None:
        return [(None, np.ones(ds.sizes["member"], dtype=bool))]
    if group not in ds or "member" not in ds[group].dims:
        fail("%s --group %s: no such parameter in the study (its parameters: %s)" %
             (option, group, ", ".join(study_parameters(ds)) or "none"))
    values = np.asarray(ds[group].values)
    label = ds[group].attrs.get("flexmoor_path", group).split(".")[-1]
    units = ds[group].attrs.get("units", "")
    out = []
    for v in np.unique(values):
        text = value_text(v)
        out.append(("%s %s%s" % (label, text, unit_suffix(units)), values == v))
    return out


def draw_rao(ds, args):
    parameter = require_parameter(ds, args.against, "--rao")
    amplitude = require_statistic(ds, args.rao, "amplitude")
    x = np.asarray(parameter.values, dtype=float)
    y, units = in_force_units(amplitude.values, amplitude.attrs.get("units", ""))
    ylabel = axis_label(amplitude, args.rao + " amplitude", units)
    if args.wave_height is not None:
        half, height_units = wave_amplitude(ds, args.wave_height)
        y = y / half
        ylabel = "RAO of %s [%s/%s]" % (args.rao, units, height_units)
    ok = complete(ds) & np.isfinite(y)
    plt = pyplot()
    figure, ax = plt.subplots(figsize=(8.0, 4.8), constrained_layout=True)
    for k, (label, members) in enumerate(groups_of(ds, args.group, "--rao")):
        chosen = ok & members
        order = np.argsort(x[chosen])
        ax.plot(x[chosen][order], y[chosen][order], "o-", color="C%d" % (k % 10), linewidth=1.4,
                markersize=5, label=label or ylabel.split(" [")[0])
    if (~complete(ds)).any():
        ax.plot([], [], " ", label="%d members failed (left out)" % (~complete(ds)).sum())
    ax.set_xlabel(axis_label(parameter, args.against))
    ax.set_ylabel(ylabel)
    ax.set_ylim(bottom=0.0)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False)
    return figure, "response-amplitude curve of %d members" % ok.sum()


def draw_extremes(ds, args):
    parameter = require_parameter(ds, args.against, "--extremes")
    x = np.asarray(parameter.values, dtype=float)
    statistics = []
    for statistic, marker, title in (("max", "o", "maximum"), ("mpm", "^", "MPM")):
        if "%s_%s" % (args.extremes, statistic) in ds or statistic == "max":
            variable = require_statistic(ds, args.extremes, statistic)
            if statistic == "mpm":
                title = "MPM (%s h, %s)" % (
                    number_text(float(variable.attrs.get("mpm_duration", np.nan)) / 3600.0),
                    variable.attrs.get("mpm_fit", "?"))
            statistics.append((variable, marker, title))
    ok = complete(ds)
    plt = pyplot()
    figure, ax = plt.subplots(figsize=(8.0, 5.0), constrained_layout=True)
    groups = groups_of(ds, args.group, "--extremes")
    every = np.concatenate([np.asarray(v.values, dtype=float) for v, _, _ in statistics])
    largest = np.abs(every[np.isfinite(every)]).max() if np.isfinite(every).any() else 0.0
    for s, (variable, marker, title) in enumerate(statistics):
        y, units = in_force_units(variable.values, variable.attrs.get("units", ""), largest)
        valid = ok & np.isfinite(y)
        for k, (label, members) in enumerate(groups):
            chosen = valid & members
            ax.plot(x[chosen], y[chosen], marker, color="C%d" % (k % 10), markersize=6,
                    markerfacecolor="none" if s else "C%d" % (k % 10), linestyle="none",
                    label="%s, %s" % (title, label) if label else title)
        levels = np.unique(x[valid])
        means = [y[valid & (x == v)].mean() for v in levels]
        ax.plot(levels, means, "-" if s == 0 else "--", color="0.25", linewidth=1.5,
                label="%s, mean%s" % (title, " over the groups" if args.group else ""))
    ax.set_xlabel(axis_label(parameter, args.against))
    ax.set_ylabel("%s [%s]" % (args.extremes, units))
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False, ncol=2 if len(groups) > 3 else 1)
    return figure, "extremes of %d members" % ok.sum()


def draw_psd(ds, args):
    psd = require_statistic(ds, args.psd, "psd")
    if "frequency" not in ds:
        fail("the study has no 'frequency' axis for %s_psd" % args.psd)
    omega = np.asarray(ds.frequency.values, dtype=float)
    ok = complete(ds)
    spectra = np.asarray(psd.values, dtype=float)
    # Forces in kN or MN as in the other figures: chosen from the largest maximum when it was
    # collected, else from the largest 4 sqrt(m0).
    maximum = "%s_max" % args.psd
    if maximum in ds and np.isfinite(ds[maximum].values).any():
        largest = np.nanmax(np.abs(ds[maximum].values))
    else:
        m0 = np.nansum(np.where(spectra > 0.0, spectra, 0.0), axis=-1) * (omega[1] - omega[0] if omega.size > 1 else 1.0)
        largest = 4.0 * np.sqrt(np.max(m0)) if m0.size else 0.0
    spectra, units = in_force_units(spectra, psd.attrs.get("units", ""), largest)
    plt = pyplot()
    figure, ax = plt.subplots(figsize=(8.0, 4.8), constrained_layout=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, max(1, ok.sum())))
    drawn, top = 0, omega.min()
    for member in np.flatnonzero(ok):
        values = spectra[member]
        if not np.isfinite(values).any():
            continue
        top = max(top, energy_top(omega, values))
        number = int(ds.member.values[member]) if "member" in ds else member + 1
        ax.plot(omega, values, color=colours[drawn], linewidth=1.2,
                label=textwrap.fill("member %d: %s" % (number, parameter_text(ds, member)), 50))
        drawn += 1
    if drawn == 0:
        fail("no complete member has %s_psd" % args.psd)
    ax.set_xlabel(axis_label(ds.frequency, "circular frequency"))
    ax.set_ylabel("%s spectral density [%s]" % (args.psd, units))
    ax.set_xlim(omega.min(), top)
    ax.set_ylim(bottom=0.0)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", frameon=False, ncol=2 if drawn > 6 else 1)
    return figure, "%d response spectra" % drawn


