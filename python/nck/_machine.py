"""nck.Machine and nck.Run: load a machine folder, run NC programs on it."""
from . import _args, _nck, _scenario
from ._closed import closed
from ._errors import ArgumentError


class Run:
    """A finished run of ``Machine.run`` (what ``nck run`` writes, in memory).

    Attributes:
        exit: the exit code ``nck run`` would give (0 program end, 1 NC error
            or a limit, see docs/cli.md).
        time_s: simulated time at the end, s.
        end: why the run ended ("program_end", "error", "max_time", "stop_at",
            "max_trace" ...), the --final document's "end".
        errors: the errors, dicts with id, ch, line, file, msg.
        warnings: the warnings (also those of the machine data), same dicts.
        events: list of dicts, one per event, the --events JSONL schema
            (docs/outputs.md); made from the compact form when first read.
        event_records: the same events as a numpy structured array, 22
            bytes each: t (float64, s), ch (uint8), ev (uint8, the index
            of its kind in ``nck.EVENT_KINDS``), line (uint32), n (int64,
            -1: no N number); ``event(i)`` is row i's dict.
        event_bytes: the memory the kept events take (their compact form,
            which ``max_events_mb`` bounds).
        final: dict, the --final JSON document.
        trace: dict of numpy float64 arrays, one per --trace CSV column
            ("t", "X", "S1.rpm" ...), full precision; None unless the run was
            asked for ``trace_every=N``.
        messages: what ``nck run`` would have printed on stderr.
    """

    def __init__(self, result):
        self._r = result

    # Pickling (a batch's worker returns a Run; a process pool sends it
    # back): the compiled result cannot cross processes, so its public
    # values go as plain data and come back as a _PlainResult that answers
    # the same attribute reads.
    def __getstate__(self):
        r = self._r
        return {name: getattr(r, name) for name in _PlainResult.FIELDS}

    def __setstate__(self, state):
        self._r = _PlainResult(state)

    exit = property(lambda self: self._r.exit)
    time_s = property(lambda self: self._r.time_s)
    end = property(lambda self: self._r.end)
    errors = property(lambda self: self._r.errors)
    warnings = property(lambda self: self._r.warnings)
    events = property(lambda self: self._r.events)
    event_records = property(lambda self: self._r.event_records)
    event_bytes = property(lambda self: self._r.event_bytes)
    final = property(lambda self: self._r.final)
    trace = property(lambda self: self._r.trace)
    messages = property(lambda self: list(self._r.messages))

    def event(self, i):
        """Event i (negative: from the end) as its dict, without making
        the dicts of all of them (``events``)."""
        return self._r.event(_args.whole(i, "i", -_args.LARGEST))

    def summary(self):
        """The one-line summary ``nck run`` ends with: end reason, cycle
        time, blocks, errors, warnings, waits."""
        return self._r.summary

    def __repr__(self):
        return f"<nck.Run exit={self.exit} end={self.end} time_s={self.time_s:.3f} errors={len(self.errors)}>"


class _PlainResult:
    """A Run's values as plain data (an unpickled Run): the attributes of
    the compiled result, and event(i) from the event dicts."""

    FIELDS = ("exit", "time_s", "end", "summary", "messages", "errors", "warnings", "events", "event_records",
              "event_bytes", "final", "trace")

    def __init__(self, state):
        missing = [name for name in self.FIELDS if name not in state]
        if missing:
            raise ArgumentError(f"a pickled nck.Run without {', '.join(missing)}", _args.BAD_ARGUMENT)
        self.__dict__.update({name: state[name] for name in self.FIELDS})

    def event(self, i):
        n = len(self.events)
        if not -n <= i < n:
            raise ArgumentError(f"event({i}): the run kept {n} event(s)", _args.BAD_ARGUMENT)
        return self.events[i]


class Machine:
    """A machine folder (startup.lis and the lists it names), loaded and checked.

    ``Machine(path)`` raises ``nck.ConfigError`` (with ``.id``, ``.file``,
    ``.line``, ``.message`` and ``.diagnostics``, all of them) when the data
    is bad. The machine is immutable: every run and session works on a copy.

    Example::

        m = nck.Machine("examples/mill")
        r = m.run("examples/mill/contour.nc")
        print(r.exit, r.time_s)
    """

    def __init__(self, path):
        """Loads and checks the machine folder `path` (ConfigError when it
        cannot be used; warnings are in ``.warnings``)."""
        self._m = _nck._Machine(_args.path(path, "path"))

    @property
    def path(self):
        """The folder it was loaded from."""
        return self._m.path

    @property
    def channels(self):
        """Per channel, its path axes' names: [["X", "Y", "Z"]]."""
        return self._m.channels

    @property
    def warnings(self):
        """The warnings loading found (dicts with id, ch, line, file, msg)."""
        return self._m.warnings

    def run(self, program, plc=None, start_at=None, stop_at=None, trace_every=None, max_time=86400.0,
            max_wall=None, max_trace_mb=512, events=True, max_events_mb=256, override=None, feedhold=None,
            trace_columns="path.v"):
        """Runs a program to its end, as ``nck run MACHINE PROGRAM`` does,
        in this process, and returns a ``Run``.

        Args:
            program: the NC program's path, or a list of them (one per channel).
            plc: a --plc scenario file (docs/plc-scenario.md), or its lines
                as a list of str (["0.5 feedhold on", "1.0 feedhold off"]):
                no file needed.
            start_at: a block search: "N100[:pass][@program]", "block:K" or
                "offset:BYTES" (docs/operating.md).
            stop_at: where the run ends: "N100", "line:12", "block:7",
                "event:wait" (docs/cli.md --stop-at).
            trace_every: keep every N-th cycle's trace row as numpy columns
                (``Run.trace``). Memory: rows x columns x 8 bytes, e.g. a
                100 s run at 1 ms with 6 columns and N=1 is 4.8 MB (growth
                may hold up to twice that for a moment).
            trace_columns: the trace's columns after the CSV's default ones,
                as --trace-columns names them: "path.v" (the default: each
                channel's path velocity, mm/s), "path.a", "path.j", a list
                or a comma-separated str of them; None: the CSV's only.
            max_time: simulated-time limit, s (the run then ends "max_time").
            max_wall: wall-clock limit, s (None: none).
            max_trace_mb: the trace's memory limit; reaching it ends the run
                ("max_trace", error 940200) rather than exhaust memory.
            events: False keeps no events (``Run.events`` is []): less
                memory and time for a long program whose events you do
                not read.
            max_events_mb: the memory limit of the kept events (their
                compact form, about 80-200 bytes each); reaching it ends the
                run ("max_events", error 940204) rather than exhaust memory.
                ``Run.events``' dicts take several times more when read;
                ``Run.event_records`` 22 bytes per event.
            override: channel 1's feed override in % from the start (the
                scenario's "0 feed_override P"), or a dict {"feed": 80,
                "rapid": 50, "S1": 120}; 0..200 as the HLI takes it, the
                path at most 100 % (docs/decisions.md, "feed override").
            feedhold: (on_s, off_s): channel 1 holds between these times;
                or a list of such pairs.

        override and feedhold are scenario lines too, before the plc's own:
        a plc line at the same time acts after them.

        Raises:
            ProgramError: the program does not exist, the scenario has an
                error, or the run cannot start.
            ArgumentError: an argument nck cannot use.

        An NC error while running does not raise: ``Run.exit`` is 1 and
        ``Run.errors`` lists it.
        """
        plc_file, plc_texts = _scenario.plc_inputs(plc, override, feedhold)
        result = self._m.run(_args.paths(program, "program"), plc_file, plc_texts,
                             _args.text(start_at, "start_at", optional=True),
                             _args.text(stop_at, "stop_at", optional=True),
                             _args.whole(trace_every, "trace_every", 1, optional=True) or 0,
                             _scenario.trace_columns(trace_columns), _args.positive(max_time, "max_time"),
                             _args.optional_positive(max_wall, "max_wall"),
                             _args.positive(max_trace_mb, "max_trace_mb"), bool(events),
                             _args.positive(max_events_mb, "max_events_mb"))
        return Run(result)

    def session(self, program=None, plc=None, max_events_mb=256):
        """Opens a live ``Session`` on this machine: nothing runs until you
        step it; see ``nck.Session``.

        Args:
            program: the program (or a list, one per channel); None: the
                channels wait for MDI and jogging.
            plc: a --plc scenario that runs alongside.
            max_events_mb: the memory limit of the events waiting for
                ``Session.events()``; past it the oldest half is dropped
                and a warning event 940205 says so (a ring: the session
                goes on).
        """
        from ._session import Session
        return Session(self, program, plc, max_events_mb)

    # -- closing -----------------------------------------------------------
    def close(self):
        """Frees the machine's data (the sessions open on it keep what they
        use); any later call raises ArgumentError 940201. Closing twice is
        allowed."""
        self._m = closed("machine")

    @property
    def closed(self):
        """True after close()."""
        return not self._m

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __repr__(self):
        if self.closed:
            return "<nck.Machine closed>"
        return f"<nck.Machine {self.path!r} channels={self.channels}>"
