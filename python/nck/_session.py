"""nck.Session: a machine running cycle by cycle, operated from Python."""
from . import _args, _nck
from ._args import whole as _whole
from ._closed import alive, closed
from ._errors import ArgumentError


def _number(value, name):
    """The value as the session takes it: six significant digits (the
    precision it has always had)."""
    return float(f"{_args.number(value, name):g}")


class Session:
    """A live session: the machine runs only when stepped, and in between
    the operator acts as on the machine's panel.

    Every operation is the typed action a line of the --plc scenario grammar
    builds (docs/plc-scenario.md), checked by the very code ``nck serve``
    uses; ``action(line)`` takes any such line as text. ``ch`` selects the
    channel (1..).

    Unlike ``nck run``, the simulated operator does not press cycle start by
    itself ("auto_cycle_start off"): after M0/M1, single step, ``stop()`` or
    a stop-at mark the channel holds until ``cycle_start()``. A program
    given here starts running at the first step.

    An NC error ends the program (see ``errors()``, ``events()``), not the
    session: MDI, jogging and reset still work. Threads may share a
    session: its calls take turns (one that finds it busy waits, without
    the GIL; Ctrl-C ends the wait). A call from inside one of its own calls
    (a ``__del__`` or gc callback in the same thread) raises
    ``SessionBusy``.

    Example::

        s = nck.Machine("examples/mill").session("examples/mill/contour.nc")
        s.run_until(line=5)
        s.override(feed=50)
        s.step(1000)
        print(s.state()["channels"][0]["axes"]["X"]["mcs"])
    """

    def __init__(self, machine, program=None, plc=None, max_events_mb=256):
        self._machine = machine
        self._s = _nck._Session(alive(machine._m), _args.paths(program, "program"), _args.optional_path(plc, "plc"),
                                _args.positive(max_events_mb, "max_events_mb"))

    # -- running -----------------------------------------------------------
    def step(self, cycles=1):
        """Runs `cycles` kernel cycles (0 or more)."""
        self._s.step(_whole(cycles, "cycles"))

    def run_until(self, block=None, line=None, event=None, time_s=None, max_cycles=10_000_000):
        """Runs cycles until a condition comes; True then. False when
        nothing would change any more without the operator (every channel
        idle, ended, in error or holding for cycle start, none jogging, the
        --plc scenario done) or `max_cycles` passed first.

        Args:
            block: a block numbered N<block> starts (int, or "N100").
            line: a block of this main-program line starts.
            event: the first event of this "ev" kind ("wait", "error", "stop"
                ...), docs/outputs.md.
            time_s: simulated time reaches this many seconds.
        """
        if isinstance(block, str):
            if not block[:1] in ("N", "n") or not block[1:].isdigit():
                raise ArgumentError(f"block {block!r} is not N<number>", 940201)
            block = int(block[1:])
        if block is None and line is None and event is None and time_s is None:
            raise ArgumentError("run_until needs block, line, event or time_s", 940201)
        until = _nck._Until(_whole(block, "block", optional=True),
                            _whole(line, "line", 0, 2**32 - 1, optional=True),
                            _args.text(event, "event", optional=True),
                            None if time_s is None else _args.number(time_s, "time_s"))
        return self._s.run_until(until, _whole(max_cycles, "max_cycles"))

    # -- the operator ------------------------------------------------------
    def action(self, line):
        """Any operator line of the scenario grammar, e.g. "ch=2 feedhold on"
        (docs/plc-scenario.md); ActionError when malformed or refused."""
        self._s.action(_args.text(line, "line"))

    def cycle_start(self, ch=1):
        """Cycle start, as nck serve's: on a channel that runs no program
        (idle, after its end, a reset or an error) while the session has one
        for it and no other channel runs one, the programs start again — a
        new run (time from 0) that keeps the operator's switches (overrides,
        single step, optional stop, mode, skip levels), the events not yet
        taken and the errors. Otherwise it releases the channel's hold
        (M0/M1, single step, stop)."""
        self._s.cycle_start(_whole(ch, "ch", 1))

    def hold(self, on=True, ch=1):
        """Feedhold on (the path brakes and waits) or off."""
        self._s.feedhold(_whole(ch, "ch", 1), bool(on))

    def stop(self, ch=1):
        """NC stop: the path brakes and the channel holds until cycle_start()."""
        self._s.stop(_whole(ch, "ch", 1))

    def reset(self, ch=1):
        """Channel reset: the program ends (reason reset)."""
        self._s.reset(_whole(ch, "ch", 1))

    def single_step(self, on=True, ch=1):
        """Single-step mode: the channel holds at every block end."""
        self._s.single_step(_whole(ch, "ch", 1), bool(on))

    def optional_stop(self, on=True, ch=1):
        """The optional-stop switch: M1 holds while on."""
        self._s.optional_stop(_whole(ch, "ch", 1), bool(on))

    def skip(self, mask, ch=1):
        """Active block-skip levels as a bit mask (bit 0: /1 ...)."""
        self._s.skip_mask(_whole(ch, "ch", 1), _whole(mask, "mask"))

    def override(self, feed=None, rapid=None, spindle=None, ch=1):
        """Overrides in %: feed (the channel's), rapid (the channel's G0
        override; it acts as the machine's g00_override_mode, P-CHAN-00181,
        says — with NOT_USED, the default, G0 takes the feed override),
        spindle (a value for S1, or a dict {"S2": 80}), all of channel ch."""
        if feed is not None:
            self._s.feed_override(_whole(ch, "ch", 1), _number(feed, "feed"))
        if rapid is not None:
            self._s.rapid_override(_whole(ch, "ch", 1), _number(rapid, "rapid"))
        if spindle is not None:
            spindles = spindle if isinstance(spindle, dict) else {"S1": spindle}
            for name, value in spindles.items():
                self._s.spindle_override(_whole(ch, "ch", 1), str(name), _number(value, "spindle"))

    def mdi(self, text, ch=1):
        """Runs one NC block typed by the operator (the channel must not be
        running a program). One cycle runs to decode it; an error in the
        text raises ProgramError, and the session stays usable."""
        self._s.mdi(_args.text(text, "text"), _whole(ch, "ch", 1))

    def jog(self, axis, direction, speed=None, ch=1):
        """Jogs an axis (mode manual): direction "+", "-" or "stop"; speed
        in mm/min (the axis's jog speed when None)."""
        self._s.jog(_whole(ch, "ch", 1), str(axis), str(direction),
                    None if speed is None else _number(speed, "speed"))

    def jog_increment(self, axis, step, ch=1):
        """Moves an axis by `step` mm (signed), mode manual."""
        self._s.jog_increment(_whole(ch, "ch", 1), str(axis), _number(step, "step"))

    def mode(self, name, ch=1):
        """"manual" (jogging) or "automatic"."""
        self._s.mode(_whole(ch, "ch", 1), str(name))

    # -- reading -----------------------------------------------------------
    def state(self):
        """The state now: the document of nck serve's GET /api/v1/state (one
        writer): per channel program_state, axes (mcs, pcs), modal state,
        path_velocity_mm_s, distance_to_go_mm, wait, the operator's switches
        (feed_override_pct, feedhold ...) and last_error; spindles (keyed by
        name); last_error; and the session's earlier fields beside it (the
        --final schema's offsets, tool, HLI; per channel ch, status, line, n,
        file; time "t"). docs/python.md."""
        return self._s.state()

    def events(self):
        """The events (dicts of the JSONL schema) since the last call, the
        operator's actions among them ("ev": "operator", "action":
        "feed_override 50"). At most ``max_events_mb`` of them wait: past it
        the oldest half goes and a ``warning`` event 940205 says so."""
        return self._s.events()

    def errors(self):
        """Every NC error of the session so far (dicts: id, ch, line, file, msg,
        then the diagnostic's one shape: severity, name, message, remedy, channel)."""
        return self._s.errors()

    @property
    def time_s(self):
        """Simulated time, s."""
        return self._s.time_s

    @property
    def cycles(self):
        """Kernel cycles run."""
        return self._s.cycles

    # -- closing -----------------------------------------------------------
    def close(self):
        """Ends the session and frees its simulation (a call another thread
        is making finishes first, on the simulation it holds); any later
        call raises ArgumentError 940201. Closing twice is allowed."""
        self._s = closed("session")

    @property
    def closed(self):
        """True after close()."""
        return not self._s

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __repr__(self):
        if self.closed:
            return "<nck.Session closed>"
        return f"<nck.Session t={self.time_s:.3f} s cycles={self.cycles}>"
