"""Bad arguments get nck's typed errors with an ID (issue 45): never an
AttributeError, OverflowError, a TypeError from the binding or a crash.
Before, nck.parse(prog, machine="dir") raised AttributeError, channel=inf
OverflowError, and 10**30 or a float where the core takes a whole number
the binding's TypeError."""
import pytest

import nck
from conftest import EXAMPLES

PROG = EXAMPLES / "mill" / "contour.nc"
HOSTILE = [float("inf"), float("-inf"), float("nan"), 10**30, -10**30, -1, 1.5, "x", b"x", object(), [1], True]


def raises_typed(call):
    """call() either returns or raises an nck.Error with an ID."""
    try:
        call()
    except nck.Error as e:
        assert e.id > 0 and e.message
        return e
    return None


def test_parse_takes_a_machine_folder_and_refuses_bad_channels(tmp_path):
    assert nck.parse(PROG, machine=EXAMPLES / "mill") == nck.parse(PROG, machine=nck.Machine(EXAMPLES / "mill"))
    assert nck.parse(PROG, machine=str(EXAMPLES / "mill"), channel=1)
    with pytest.raises(nck.ConfigError):
        nck.parse(PROG, machine=tmp_path / "nowhere")
    for bad in (float("inf"), float("nan"), 10**30, 0, -1, 1.5, "1", None):
        with pytest.raises(nck.ArgumentError) as e:
            nck.parse(PROG, channel=bad)
        assert e.value.id == 940201 and "channel" in e.value.message
    with pytest.raises(nck.ArgumentError) as e:
        nck.parse(PROG, machine=EXAMPLES / "mill", channel=2)
    assert "no channel 2" in e.value.message
    for bad in (-1, float("inf"), "x"):
        with pytest.raises(nck.ArgumentError):
            nck.parse(PROG, max_wall=bad)
    with pytest.raises(nck.ArgumentError):
        nck.parse(PROG, machine=42)


RUN_ARGUMENTS = ["plc", "start_at", "stop_at", "trace_every", "max_time", "max_wall", "max_trace_mb",
                 "max_events_mb"]


@pytest.mark.parametrize("name", RUN_ARGUMENTS)
def test_machine_run_arguments(mill, name):
    for bad in HOSTILE:
        raises_typed(lambda: mill.run(PROG, max_time=0.01, **{name: bad}) if name != "max_time"
                     else mill.run(PROG, max_time=bad))


@pytest.mark.parametrize("call", [
    lambda m, v: m.run(v, max_time=0.01),
    lambda m, v: nck.Machine(v),
    lambda m, v: m.session(v),
    lambda m, v: m.session(PROG, plc=v),
    lambda m, v: nck.parse(v),
], ids=["run.program", "Machine", "session.program", "session.plc", "parse.program"])
def test_paths(mill, call):
    for bad in HOSTILE:
        raises_typed(lambda: call(mill, bad))


SESSION_CALLS = {
    "step": lambda s, v: s.step(v),
    "run_until.block": lambda s, v: s.run_until(block=v, max_cycles=5),
    "run_until.line": lambda s, v: s.run_until(line=v, max_cycles=5),
    "run_until.event": lambda s, v: s.run_until(event=v, max_cycles=5),
    "run_until.time_s": lambda s, v: s.run_until(time_s=v, max_cycles=5),
    "run_until.max_cycles": lambda s, v: s.run_until(line=1, max_cycles=v),
    "action": lambda s, v: s.action(v),
    "cycle_start.ch": lambda s, v: s.cycle_start(v),
    "hold.ch": lambda s, v: s.hold(True, ch=v),
    "skip": lambda s, v: s.skip(v),
    "override.feed": lambda s, v: s.override(feed=v),
    "override.rapid": lambda s, v: s.override(rapid=v),
    "override.spindle": lambda s, v: s.override(spindle=v),
    "mdi": lambda s, v: s.mdi(v),
    "jog.axis": lambda s, v: s.jog(v, "+"),
    "jog.direction": lambda s, v: s.jog("X", v),
    "jog.speed": lambda s, v: s.jog("X", "+", v),
    "jog_increment": lambda s, v: s.jog_increment("X", v),
    "mode": lambda s, v: s.mode(v),
}


@pytest.mark.parametrize("name", SESSION_CALLS)
def test_session_arguments(mill, name):
    s = mill.session(PROG)
    for bad in HOSTILE:
        if name == "step" and bad in (10**30, True):  # a valid count far too long to wait for: see below
            continue
        raises_typed(lambda: SESSION_CALLS[name](s, bad))
    s.step(5)  # the session is whole
    assert s.cycles >= 5


def test_a_count_beyond_what_the_core_holds_is_refused(mill):
    s = mill.session(PROG)
    for call in (lambda: s.step(2**63), lambda: s.run_until(line=2**32), lambda: s.run_until(block=2**63)):
        with pytest.raises(nck.ArgumentError):
            call()


def test_run_event_index(mill):
    r = mill.run(PROG)
    for bad in (len(r.events), -len(r.events) - 1, 10**30, 1.5, "0", None):
        with pytest.raises(nck.ArgumentError):
            r.event(bad)
