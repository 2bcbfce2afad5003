"""nck: run, step, inspect and test NC programs from Python.

The same library ``nck run`` uses, in this process (no subprocess):

    import nck
    m = nck.Machine("examples/mill")          # ConfigError on bad data
    r = m.run("examples/mill/contour.nc")     # a Run: exit, time_s, events, final, trace
    s = m.session("examples/mill/contour.nc") # a Session: step, operate, read the state
    nck.batch([(m.path, "examples/mill/contour.nc")], workers=2)
    nck.check("examples/mill", "examples/mill/contour.nc")  # nck check --json

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

__all__ = ["Machine", "Run", "Session", "batch", "check", "parse", "errors", "params", "EVENT_KINDS",
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


def check(machine, programs=None, strict=False, max_wall=None):
    """The pre-flight check of ``nck check MACHINE PROGRAM... --json``: the
    machine data's plausibility and, with programs, each program decoded
    and prepared as a run would, without running it; every error and
    warning, not only the first (docs/cli.md).

    Args:
        machine: a machine folder's path, or an ``nck.Machine`` (its folder
            is read again: the check's own warnings come with it).
        programs: a program's path or a list, one per channel (None: the
            machine data only).
        strict: every unknown list key is an error (910032), as --strict.
        max_wall: wall-clock limit, s (None: none); reaching it adds error
            940006 at the program whose check it ended (the command exits 1).

    Returns:
        The command's JSON array as dicts, the machine data's first: id,
        name, severity ("error"/"warning"), channel (0: machine data), file,
        line, column, message. Bad data is a finding, not an exception
        (``any(d["severity"] == "error" for d in ...)`` is the command's exit 1).

    Raises:
        ProgramError: a program does not exist (940202).
        ArgumentError: more programs than channels, or a bad argument (940201).

    Ctrl-C stops the check at its next block and raises KeyboardInterrupt.
    """
    folder = _alive(machine._m).path if isinstance(machine, Machine) else _args.path(machine, "machine")
    wall = _args.optional_positive(max_wall, "max_wall")
    return _nck.check(folder, _args.paths(programs, "programs"), bool(strict), wall)


def errors():
    """The catalogue of diagnostic IDs: dicts with id, severity, name, cause,
    remedy, as GET /api/v1/errors gives them, and text (= cause; docs/errors.md)."""
    return _nck.errors()


def params():
    """Every list parameter nck reads: dicts with key, id, list, min, max,
    default, unit, meaning (docs/parameters.md)."""
    return _nck.params()
