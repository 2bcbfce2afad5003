"""nck: run, step, inspect and test NC programs from Python.

The same library ``nck run`` uses, in this process (no subprocess):

    import nck
    m = nck.Machine("examples/mill")          # ConfigError on bad data
    r = m.run("examples/mill/contour.nc")     # a Run: exit, time_s, events, final, trace
    s = m.session("examples/mill/contour.nc") # a Session: step, operate, read the state
    nck.batch([(m.path, "examples/mill/contour.nc")], workers=2)

docs/python.md documents the API with examples.
"""
from . import _nck
from ._errors import ActionError, ArgumentError, ConfigError, Error, ProgramError
from ._machine import Machine, Run
from ._session import Session
from ._batch import batch

__all__ = ["Machine", "Run", "Session", "batch", "parse", "errors", "params",
           "Error", "ConfigError", "ProgramError", "ActionError", "ArgumentError"]


def parse(program, machine=None, channel=1, max_wall=None):
    """Decodes a program without running it: its blocks as dicts of the
    ``nck parse --json`` schema.

    Args:
        program: the NC program's path.
        machine: an ``nck.Machine`` whose axis and spindle names to use
            (default: X Y Z A B C U V W, S1 S2 S3).
        channel: the machine's channel (1..).
        max_wall: wall-clock limit, s (None: none); reaching it is an error.

    Raises:
        ProgramError: the file does not exist, or has errors (``.diagnostics``
            lists every one: decoding goes on past a bad block).
    """
    import os
    m = machine._m if machine is not None else None
    return _nck.parse(os.fspath(program), m, int(channel), float(max_wall or 0))


def errors():
    """Every diagnostic ID: dicts with id, severity, name, text, remedy (docs/errors.md)."""
    return _nck.errors()


def params():
    """Every list parameter nck reads: dicts with key, id, list, min, max,
    default, unit, meaning (docs/parameters.md)."""
    return _nck.params()
