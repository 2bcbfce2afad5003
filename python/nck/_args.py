"""Arguments checked before they reach the compiled core: a value nck
cannot use raises ``ArgumentError`` (940201) that names the argument, not a
TypeError, OverflowError or AttributeError from deep inside (issue 45:
``parse(machine="dir")`` and ``channel=inf`` did)."""
import math
import numbers
import os

from ._errors import ArgumentError

BAD_ARGUMENT = 940201
#: The largest count the core takes (it holds counts in 64-bit integers).
LARGEST = 2**62


def fail(name, wanted, value):
    raise ArgumentError(f"{name} must be {wanted}, not {value!r}", BAD_ARGUMENT)


def path(value, name):
    """A file or folder path as str."""
    if isinstance(value, (str, os.PathLike)):
        p = os.fspath(value)
        if isinstance(p, str):
            return p
    fail(name, "a path (str or os.PathLike)", value)


def optional_path(value, name):
    """A path, or "" for None."""
    return "" if value is None else path(value, name)


def paths(value, name):
    """One path, or a list of paths (program i runs in channel i+1)."""
    if value is None:
        return []
    if isinstance(value, (str, os.PathLike)):
        return [path(value, name)]
    if isinstance(value, (list, tuple)):
        return [path(p, name) for p in value]
    fail(name, "a path or a list of paths", value)


def whole(value, name, lowest=0, highest=LARGEST, optional=False):
    """A whole number in [lowest, highest] (or None when optional)."""
    if value is None and optional:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not lowest <= value <= highest:
        fail(name, f"a whole number from {lowest} to {highest}", value)
    return int(value)


def number(value, name):
    """A finite real number as float."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        fail(name, "a finite number", value)
    return float(value)


def positive(value, name):
    """A finite number above 0 as float."""
    v = number(value, name)
    if v <= 0:
        fail(name, "a positive number", value)
    return v


def optional_positive(value, name):
    """None (or 0, as before): no limit, given as 0; otherwise a positive number."""
    return 0.0 if value is None or (not isinstance(value, bool) and value == 0) else positive(value, name)


def text(value, name, optional=False):
    """A str (or None when optional)."""
    if value is None and optional:
        return None
    if not isinstance(value, str):
        fail(name, "a str", value)
    return value
