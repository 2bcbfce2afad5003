"""Session: cycle start after an end or a reset starts the program again, as
nck serve's does; the operator's actions are events (issue 47 item 7)."""
import pytest

import nck
from conftest import EXAMPLES


def channel(s):
    return s.state()["channels"][0]


def test_cycle_start_after_the_program_end_starts_it_again(mill, program):
    s = mill.session(program("G1 X5 F3000\nM30\n"))
    assert s.run_until(event="end")
    assert channel(s)["program_state"] == "ended"
    s.events()
    s.cycle_start()
    assert channel(s)["program_state"] != "ended" and s.time_s == 0  # a new run, as nck serve's
    assert s.run_until(event="end")
    assert [e["line"] for e in s.events() if e["ev"] == "block"] == [1, 2]
    assert channel(s)["axes"]["X"]["mcs"] == pytest.approx(5)


def test_cycle_start_after_a_reset_keeps_the_operators_switches_and_the_errors(mill, program):
    s = mill.session(program("G1 X100 F3000\nG1 Q=\nM30\n"))
    assert s.run_until(event="error")
    s.override(feed=40)
    s.single_step(True)
    s.reset()
    s.step(5)
    s.cycle_start()
    s.step(1)  # the switches reach the new run's HLI in its first cycle, as any action
    assert channel(s)["feed_override_pct"] == 40 and channel(s)["single_step"]
    assert len(s.errors()) == 1  # the run before kept its error
    s.single_step(False)
    s.cycle_start()  # releases the single-step hold of the new run's first block
    assert s.run_until(event="error")
    assert len(s.errors()) == 2


def test_cycle_start_releases_a_hold_as_before(mill, program):
    s = mill.session(program("G1 X5 F3000\nM0\nG1 X10\nM30\n"))
    assert not s.run_until(event="end", max_cycles=50000)
    s.cycle_start()
    assert s.time_s > 0 and s.run_until(event="end")
    assert channel(s)["axes"]["X"]["mcs"] == pytest.approx(10)


def test_a_session_without_program_has_nothing_to_start(mill):
    s = mill.session()
    s.cycle_start()
    assert channel(s)["program_state"] == "idle"


def test_operator_actions_are_events(mill, program):
    s = mill.session(program("G1 X100 F3000\nM30\n"))
    s.step(1)
    assert all(e["ev"] != "operator" for e in s.events())  # the session's own setup is none
    s.step(99)
    s.override(feed=50, spindle={"S1": 80})
    s.hold()
    s.action("ch=1 feedhold off")
    ops = [e for e in s.events() if e["ev"] == "operator"]
    assert [e["action"] for e in ops] == ["feed_override 50", "spindle_override S1 80", "feedhold on", "feedhold off"]
    assert all(e["ch"] == 1 and e["t"] == pytest.approx(0.1) for e in ops)
    assert "operator" in nck.EVENT_KINDS
    s.reset()
    s.step(2000)  # the path brakes, then the channel is idle
    s.mdi("G0 X1")
    s.cycle_start()
    assert [e["action"] for e in s.events() if e["ev"] == "operator"] == ["reset", "mdi G0 X1", "cycle_start"]


def test_a_refused_action_is_no_event(mill, program):
    s = mill.session(program("G1 X100 F3000\nM30\n"))
    s.step(10)
    with pytest.raises(nck.ActionError):
        s.mdi("G0 X1")  # a program runs
    assert not [e for e in s.events() if e["ev"] == "operator"]
