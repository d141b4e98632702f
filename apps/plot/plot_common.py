"""Helpers that every figure of `flexmoor plot` shares (flexmoor_plot.py)."""
import sys

import numpy as np


def pyplot():
    """matplotlib.pyplot (Agg), imported when a figure is drawn: a refused argument does not wait
    for it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot

    return matplotlib.pyplot


def fail(message):
    """Bad input: the message on stderr and exit code 2."""
    print("flexmoor plot: " + message, file=sys.stderr)
    sys.exit(2)


def number_text(value):
    return "%g" % value


def value_text(value):
    """A parameter's value as text: %g for numbers, text values as they are."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if np.issubdtype(np.asarray(value).dtype, np.number):
        return number_text(value)
    return str(value)
