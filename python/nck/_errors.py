"""The exceptions of nck: each carries the nck diagnostic ID and where.

``Error`` is the base of all; catch it to catch anything nck raises on bad
input. An NC error *during* a run is not an exception: it ends the program,
and ``Run.errors`` / ``Run.exit`` say so (as ``nck run`` does).
"""


class Error(Exception):
    """An nck diagnostic as an exception.

    Attributes:
        id: the diagnostic ID (``nck.errors()`` / docs/errors.md explain it).
        file: the file it concerns ("" when none).
        line: its line, 1-based (0: not known).
        message: the text.
        diagnostics: every diagnostic (dicts with id, severity, file, line,
            msg); the attributes above are the first one's.
    """

    def __init__(self, message, id=0, file="", line=0, diagnostics=None):
        super().__init__(message)
        self.id = id
        self.file = file
        self.line = line
        self.message = message
        self.diagnostics = diagnostics if diagnostics is not None else [
            {"id": id, "severity": "error", "file": file, "line": line, "msg": message}]

    @classmethod
    def from_diagnostics(cls, diagnostics):
        first = diagnostics[0] if diagnostics else {"id": 0, "file": "", "line": 0, "msg": "unknown error"}
        return cls(first["msg"], first["id"], first["file"], first["line"], list(diagnostics))

    def __str__(self):
        where = self.file or "nck"
        if self.line:
            where += f":{self.line}"
        more = f" (+{len(self.diagnostics) - 1} more)" if len(self.diagnostics) > 1 else ""
        return f"{where}: error {self.id}: {self.message}{more}"


class ConfigError(Error):
    """The machine folder cannot be used: a list is missing or has bad data."""


class ProgramError(Error):
    """A program (or MDI text) that does not exist or cannot be decoded, or a
    run that cannot start (a bad --plc scenario, a block search mark not found)."""


class ActionError(Error):
    """An operator action that is malformed or that the state does not allow
    (MDI while a program runs, an unknown axis, too many at once)."""


class ArgumentError(Error, ValueError):
    """An argument nck cannot use (a negative cycle count, a bad stop_at mark)."""


class SessionBusy(Error, RuntimeError):
    """A Session called from inside one of its own calls, in the same thread
    (a ``__del__``, a gc callback or a signal handler that ran meanwhile):
    waiting for its turn would never end (940203). Threads sharing a
    session never see it: they take turns."""
