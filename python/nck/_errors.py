"""The exceptions of nck: each carries the nck diagnostic ID and where.

``Error`` is the base of all; catch it to catch anything nck raises on bad
input. An NC error *during* a run is not an exception: it ends the program,
and ``Run.errors`` / ``Run.exit`` say so (as ``nck run`` does).
"""


class Error(Exception):
    """An nck diagnostic as an exception.

    Attributes:
        id: the diagnostic's own ID (``nck.errors()`` / docs/errors.md
            explain it), e.g. 960003 for an override above 200 %.
        severity, name, remedy: the ID's, as the catalogue gives them.
        file: the file it concerns ("" when none).
        line: its line, 1-based (0: not known).
        column: its column, 1-based (0: not known).
        channel: the channel, 1-based (0: none).
        message: the text.
        diagnostics: every diagnostic, each a dict of the one shape
            ``{id, severity, name, message, remedy, file, line, column,
            channel}`` (a field that does not apply is left out; docs/python.md)
            with ``msg`` (the message's earlier name); the attributes above
            are the first one's.
    """

    def __init__(self, message, id=0, file="", line=0, diagnostics=None):
        super().__init__(message)
        self.id = id
        self.file = file
        self.line = line
        self.message = message
        if diagnostics is None:
            first = {"id": id, "severity": "error", "message": message, "msg": message}
            if file:
                first["file"] = file
            if line:
                first["line"] = line
            diagnostics = [first]
        self.diagnostics = diagnostics
        first = diagnostics[0] if diagnostics else {}
        self.severity = first.get("severity", "error")
        self.name = first.get("name", "")
        self.remedy = first.get("remedy", "")
        self.column = first.get("column", 0)
        self.channel = first.get("channel", 0)

    @classmethod
    def from_diagnostics(cls, diagnostics):
        first = diagnostics[0] if diagnostics else {"id": 0, "message": "unknown error"}
        return cls(first.get("message", first.get("msg", "")), first["id"], first.get("file", ""),
                   first.get("line", 0), list(diagnostics))

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
