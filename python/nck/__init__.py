"""nck: run, step, inspect and test NC programs from Python.

The same library ``nck run`` uses, in this process (no subprocess):

    import nck
    m = nck.Machine("examples/mill")          # ConfigError on bad data
    r = m.run("examples/mill/contour.nc")     # a Run: exit, time_s, events, final, trace
    s = m.session("examples/mill/contour.nc") # a Session: step, operate, read the state
    nck.batch([(m.path, "examples/mill/contour.nc")], workers=2)

docs/python.md documents the API with examples.
"""
from . import _args, _nck
from ._errors import ActionError, ArgumentError, ConfigError, Error, ProgramError, SessionBusy
from ._machine import Machine, Run
from ._session import Session
from ._batch import batch
from ._closed import alive as _alive

#: The version of the nck build this module belongs to ("0.3.0": CMake's
#: project(VERSION), as ``nck --version`` prints it).
__version__ = _nck.version

#: The events' kinds ("ev"), by the code ``Run.event_records["ev"]`` holds.
EVENT_KINDS = _nck.EVENT_KINDS

__all__ = ["Machine", "Run", "Session", "batch", "parse", "errors", "params", "EVENT_KINDS",
           "Error", "ConfigError", "ProgramError", "ActionError", "ArgumentError", "SessionBusy"]


def parse(program, machine=None, channel=1, max_wall=None):
    """Decodes a program without running it: its blocks as dicts of the
    ``nck parse --json`` schema.

    Args:
        program: the NC program's path.
        machine: an ``nck.Machine``, or a machine folder's path, whose axis
            and spindle names to use (default: X Y Z A B C U V W, S1 S2 S3).
        channel: the machine's channel (1..).
        max_wall: wall-clock limit, s (None: none); reaching it is an error.

    Ctrl-C stops the decoder at its next block and raises KeyboardInterrupt.

    Raises:
        ProgramError: the file does not exist, or has errors (``.diagnostics``
            lists every one: decoding goes on past a bad block).
        ConfigError: the machine folder cannot be loaded.
        ArgumentError: an argument nck cannot use (940201).
    """
    path = _args.path(program, "program")
    if machine is not None and not isinstance(machine, Machine):
        machine = Machine(_args.path(machine, "machine"))
    ch = _args.whole(channel, "channel", 1)  # the core says when the machine has no such channel
    wall = _args.optional_positive(max_wall, "max_wall")
    return _nck.parse(path, _alive(machine._m) if machine is not None else None, ch, wall)


def errors():
    """Every diagnostic ID: dicts with id, severity, name, text, remedy (docs/errors.md)."""
    return _nck.errors()


def params():
    """Every list parameter nck reads: dicts with key, id, list, min, max,
    default, unit, meaning (docs/parameters.md)."""
    return _nck.params()
