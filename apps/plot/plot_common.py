"""Helpers that every figure of `flexmoor plot` shares (flexmoor_plot.py)."""
import re
import sys

BAD_INPUT, FAILED = 2, 4  # the exit codes of flexmoor (README, "Exit codes")


def fail(message, code=BAD_INPUT):
    """Bad input (or, with code FAILED, an output that cannot be written): the message on stderr
    and the exit code."""
    print("flexmoor plot: " + message, file=sys.stderr)
    sys.exit(code)


def missing_module(error):
    """A module of Debian's python3 packages that is not installed: exit code 4."""
    fail("cannot import %s (%s): it needs Debian's python3-matplotlib and python3-xarray "
         "(scripts/setup.sh installs them)" % (error.name or "a module", error), FAILED)


try:
    import numpy as np
except ImportError as e:
    missing_module(e)


def pyplot():
    """matplotlib.pyplot (Agg), imported when a figure is drawn: a refused argument does not wait
    for it."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot
    except ImportError as e:
        missing_module(e)
    return matplotlib.pyplot


def number_text(value):
    return "%g" % value


def value_text(value):
    """A parameter's value as text: %g for numbers, text values as they are."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if np.issubdtype(np.asarray(value).dtype, np.number):
        return number_text(value)
    return str(value)


def in_force_units(values, units, largest=None):
    """`values` and their units with newtons shown as kN or MN, chosen from the magnitude: MN
    from 1e6 N, kN from 1e3 N, else N. Units that start with N2 (a spectral density of a force)
    scale by the square. `largest`: the magnitude in N that chooses (default: the largest
    |value|; needed for N2). Other units come back as they are."""
    match = re.match(r"N(2?)(?=[ /]|$)", units or "")
    if not match:
        return values, units
    power = 2 if match.group(1) else 1
    values = np.asarray(values, dtype=float)
    if largest is None:
        finite = np.abs(values[np.isfinite(values)])
        largest = finite.max() if finite.size else 0.0
    for factor, name in ((1e6, "MN"), (1e3, "kN")):
        if largest >= factor:
            return values / factor ** power, name + units[1:]
    return values, units


def number_label(value, digits):
    """`value` to `digits` significant digits: positional from 1e-4 to 1e6 (100, 0.25), else
    with a short exponent (2e-6, 3e7)."""
    if value == 0.0:
        return "0"
    if 1e-4 <= abs(value) < 1e6:
        return np.format_float_positional(value, precision=digits, unique=False,
                                          fractional=False, trim="-")
    text = "%.*g" % (digits, value)
    return re.sub(r"e([-+])0*(\d)", lambda m: "e" + m.group(1).lstrip("+") + m.group(2), text)


def tick_labels(values):
    """Plain labels of tick values: the fewest significant digits (up to 15) that give every
    value back to a millionth of the spacing (number_label)."""
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        return []
    spacing = np.min(np.diff(np.sort(values))) if values.size > 1 else 0.0
    tolerance = 1e-6 * (spacing if spacing > 0.0 else max(abs(values).max(), 1e-300))
    values = np.where(np.abs(values) < tolerance, 0.0, values)  # 1e-17 of a zero tick
    for digits in range(1, 16):
        labels = [number_label(v, digits) for v in values]
        if all(abs(float(t) - v) <= tolerance for t, v in zip(labels, values)):
            return labels
    return labels


def plain_ticks(figure):
    """Every linear axis of `figure` labelled by tick_labels: no offset or 1e6 factor at an
    axis' end (minus signs as matplotlib writes them)."""
    import matplotlib.ticker

    class Plain(matplotlib.ticker.Formatter):
        def __call__(self, x, pos=None):
            return self.fix_minus(tick_labels([x])[0])

        def format_ticks(self, values):
            return [self.fix_minus(t) for t in tick_labels(values)]

    for ax in figure.axes:
        for axis, scale in ((ax.xaxis, ax.get_xscale()), (ax.yaxis, ax.get_yscale())):
            if scale == "linear":
                axis.set_major_formatter(Plain())


def energy_top(omega, density, fraction=0.999, margin=1.2):
    """Where a spectrum's energy is: the frequency below which `fraction` of the area under
    `density` (over evenly spaced `omega`) lies, times `margin`, at most the last frequency."""
    omega = np.asarray(omega, dtype=float)
    density = np.asarray(density, dtype=float)
    power = np.where(np.isfinite(density) & (density > 0.0), density, 0.0)
    cumulative = np.cumsum(power)
    if cumulative.size == 0 or cumulative[-1] <= 0.0:
        return omega[-1] if omega.size else 1.0
    k = min(int(np.searchsorted(cumulative, fraction * cumulative[-1])), omega.size - 1)
    return min(omega[-1], margin * omega[k])
