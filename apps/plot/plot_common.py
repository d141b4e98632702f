"""Helpers that every figure of `flexmoor plot` shares (flexmoor_plot.py)."""
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
