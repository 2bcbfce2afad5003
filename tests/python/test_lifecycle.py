"""Results that pickle, and sessions and machines that close (issue 47 item 4)."""
import pickle

import numpy as np
import pytest

import nck
from conftest import EXAMPLES


def test_a_run_pickles_with_its_values(mill):
    r = mill.run(EXAMPLES / "mill" / "contour.nc", trace_every=50)
    back = pickle.loads(pickle.dumps(r))
    assert isinstance(back, nck.Run)
    assert (back.exit, back.end, back.time_s, back.summary()) == (r.exit, r.end, r.time_s, r.summary())
    assert back.errors == r.errors and back.warnings == r.warnings and back.messages == r.messages
    assert back.events == r.events and back.event(-1) == r.event(-1) and back.event_bytes == r.event_bytes
    assert np.array_equal(back.event_records, r.event_records)
    assert back.final == r.final
    assert list(back.trace) == list(r.trace) and all(np.array_equal(back.trace[k], r.trace[k]) for k in r.trace)
    assert pickle.loads(pickle.dumps(back)).final == r.final  # and again
    with pytest.raises(nck.ArgumentError):
        back.event(len(r.events))


def test_a_run_without_trace_or_events_pickles(mill):
    r = mill.run(EXAMPLES / "mill" / "contour.nc", events=False)
    back = pickle.loads(pickle.dumps(r))
    assert back.trace is None and back.events == [] and back.time_s == r.time_s


def test_a_session_closes_at_the_end_of_its_with_block(mill, program):
    with mill.session(program("G1 X10 F1000\nM30\n")) as s:
        s.step(10)
        assert not s.closed
    assert s.closed and repr(s) == "<nck.Session closed>"
    for call in (lambda: s.step(), lambda: s.state(), lambda: s.cycle_start(), lambda: s.time_s):
        with pytest.raises(nck.ArgumentError) as e:
            call()
        assert e.value.id == 940201 and "closed" in e.value.message
    s.close()  # twice is fine


def test_a_machine_closes_and_refuses_every_use_after(program):
    with nck.Machine(EXAMPLES / "mill") as m:
        s = m.session(program("G1 X10 F1000\nM30\n"))
    assert m.closed
    with pytest.raises(nck.ArgumentError) as e:
        m.run(EXAMPLES / "mill" / "contour.nc")
    assert e.value.id == 940201 and isinstance(e.value, ValueError)
    for call in (lambda: m.session(), lambda: m.path, lambda: nck.parse(EXAMPLES / "mill" / "contour.nc", m)):
        with pytest.raises(nck.ArgumentError):
            call()
    assert s.run_until(event="end")  # a session opened before goes on
    s.close()
