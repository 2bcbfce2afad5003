"""Session: stepping, operating and reading a running machine."""
import threading

import pytest

import nck
from conftest import EXAMPLES


def x_mcs(s):
    return s.state()["channels"][0]["axes"]["X"]["mcs"]


def test_step_advances_the_kernel_cycle_by_cycle(mill):
    s = mill.session(EXAMPLES / "mill" / "contour.nc")
    assert s.cycles == 0
    s.step()
    s.step(99)
    assert s.cycles == 100 and s.time_s == pytest.approx(0.1)
    events = s.events()
    assert events and events[0]["t"] == 0 and all("ev" in e for e in events)
    assert s.events() == []  # since the last call
    s.step(0)
    assert s.cycles == 100


def test_mdi_moves_x(mill):
    s = mill.session()
    assert x_mcs(s) == pytest.approx(0)
    s.mdi("G0 X10")
    assert s.run_until(event="state", max_cycles=20000)  # running -> idle: MDI done
    assert x_mcs(s) == pytest.approx(10)


def test_feedhold_stops_the_path_and_release_goes_on(mill, program):
    s = mill.session(program("G1 X200 F3000\nM30\n"))
    s.step(300)
    assert s.state()["channels"][0]["path_velocity_mm_s"] > 0
    s.hold()
    s.step(1000)
    held = x_mcs(s)
    assert s.state()["channels"][0]["path_velocity_mm_s"] == 0
    s.step(500)
    assert x_mcs(s) == pytest.approx(held)  # stands
    s.hold(False)
    s.step(500)
    assert x_mcs(s) > held


def test_run_until_a_line_holds_there_with_the_state(mill, program):
    s = mill.session(program("G0 X1\nN20 G1 X5 F600\nG1 Y5\nM30\n"))
    assert s.run_until(line=3)
    st = s.state()["channels"][0]
    assert st["line"] == 3 and st["program_state"] == "running"
    assert st["axes"]["X"]["mcs"] == pytest.approx(5)
    s2 = mill.session(program("G0 X1\nN20 G1 X5 F600\nM30\n", "q.nc"))
    assert s2.run_until(block="N20")
    assert s2.state()["channels"][0]["n"] == 20
    assert not s2.run_until(line=99)  # the program ends first
    assert s2.state()["channels"][0]["program_state"] == "ended"


def test_m0_waits_for_cycle_start_in_a_session(mill, program):
    s = mill.session(program("G1 X5 F3000\nM0\nG1 X10\nM30\n"))
    assert not s.run_until(event="end", max_cycles=50000)  # holds: nothing releases it
    assert s.state()["channels"][0]["program_state"] == "hold"
    s.cycle_start()
    assert s.run_until(event="end", max_cycles=50000)
    assert x_mcs(s) == pytest.approx(10)


def test_feed_override_slows_the_path(mill, program):
    def velocity(percent):
        s = mill.session(program("G1 X500 F3000\nM30\n"))
        s.override(feed=percent)
        s.step(2000)
        return s.state()["channels"][0]["path_velocity_mm_s"]
    assert velocity(50) == pytest.approx(velocity(100) / 2, rel=1e-3)


def test_an_error_in_mdi_raises_and_the_session_stays_usable(mill):
    s = mill.session()
    with pytest.raises(nck.ProgramError) as e:
        s.mdi("G1 Q=")
    assert e.value.id > 0
    assert s.errors()
    s.mdi("G0 X3")
    assert s.run_until(event="state", max_cycles=20000)
    assert x_mcs(s) == pytest.approx(3)


def test_actions_the_state_does_not_allow_raise_action_error(mill):
    s = mill.session(EXAMPLES / "mill" / "contour.nc")
    s.step(10)
    with pytest.raises(nck.ActionError) as e:
        s.mdi("G0 X1")  # while the program runs
    assert e.value.id == 930710
    with pytest.raises(nck.ActionError):
        s.action("fly_to_the_moon")
    with pytest.raises(nck.ActionError):
        s.jog("Q", "+")
    with pytest.raises(nck.ArgumentError):
        s.step(-1)
    with pytest.raises(nck.ArgumentError):
        s.run_until()
    s.step(10)  # still usable


def test_jog_increment_moves_an_axis_in_manual_mode(mill):
    s = mill.session()
    s.mode("manual")
    s.jog_increment("X", -0.5)
    s.step(3000)
    assert x_mcs(s) == pytest.approx(-0.5)


def test_state_has_spindles_hli_and_time(mill):
    s = mill.session(EXAMPLES / "mill" / "contour.nc")
    s.step(50)
    st = s.state()
    assert st["cycle"] == 50
    assert "S1" in st["spindles"] and "hli" in st
    assert {"mcs", "pcs"} <= set(st["channels"][0]["axes"]["X"])


def test_run_until_refuses_an_unknown_event_kind(mill):
    s = mill.session()
    with pytest.raises(nck.ArgumentError):
        s.run_until(event="nonsense")
    assert s.state()["t"] == 0 and s.cycles == 0


ENDLESS = "N10 G90\n$WHILE 1 == 1\n  G1 X10 F6000\n  G1 X0\n$ENDWHILE\nM30\n"


def interrupt_after(seconds):
    import os
    import signal
    import threading
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_stops_a_long_step_and_the_session_goes_on(mill, program):
    import time
    s = mill.session(program(ENDLESS))
    interrupt_after(0.3)
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        s.step(10**9)
    assert time.perf_counter() - start < 10
    cycles = s.cycles
    s.step(10)
    assert s.cycles == cycles + 10 and s.state()["channels"][0]["program_state"] == "running"


def test_ctrl_c_stops_a_long_run(mill, program):
    import time
    interrupt_after(0.3)
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        mill.run(program(ENDLESS), events=False)
    assert time.perf_counter() - start < 10
    assert mill.run(EXAMPLES / "mill" / "contour.nc").exit == 0  # the next run is not stopped


def test_rapid_override_slows_g0_only(mill, program):
    # examples/mill: g00_override_mode MINIMUM_OF_G0_G1 (P-CHAN-00181)
    def velocity(text, rapid):
        s = mill.session(program(text))
        s.override(rapid=rapid)
        s.step(1000)
        return s.state()["channels"][0]["path_velocity_mm_s"]
    assert velocity("G0 X500\nM30\n", 50) == pytest.approx(velocity("G0 X500\nM30\n", 100) / 2, rel=1e-3)
    assert velocity("G1 X500 F3000\nM30\n", 50) == pytest.approx(50, rel=1e-3)


# Each call builds its typed action; refused, it says what its scenario line
# (read by action(line)) says, word for word.
@pytest.mark.parametrize("call, line", [
    (lambda s: s.override(feed=300), "ch=1 feed_override 300"),
    (lambda s: s.override(feed=1e6), "ch=1 feed_override 1e+06"),
    (lambda s: s.override(spindle={"S9": 50}), "override S9 50"),
    (lambda s: s.override(spindle={"X1": 50}), "override X1 50"),
    (lambda s: s.hold(True, ch=3), "ch=3 feedhold on"),
    (lambda s: s.hold(True, ch=99), "ch=99 feedhold on"),
    (lambda s: s.skip(0x400), "ch=1 skip_mask 0x400"),
    (lambda s: s.jog("Q", "+", 600), "ch=1 jog Q + 600"),
    (lambda s: s.jog("X", "up"), "ch=1 jog X up"),
    (lambda s: s.jog("1X", "+"), "ch=1 jog 1X +"),
    (lambda s: s.jog("X", "+", 0), "ch=1 jog X + 0"),
    (lambda s: s.jog("X", "stop", 600), "ch=1 jog X stop 600"),
    (lambda s: s.jog("ABCDEFGHIJKLMNOPQ", "+"), "ch=1 jog ABCDEFGHIJKLMNOPQ +"),
    (lambda s: s.jog_increment("X", 0), "ch=1 jog_increment X + 0"),
    (lambda s: s.jog_increment("Q", -0.5), "ch=1 jog_increment Q - 0.5"),
    (lambda s: s.mode("fast"), "ch=1 mode fast"),
    (lambda s: s.mdi("# only"), "ch=1 mdi # only"),
    (lambda s: s.mdi("G0 X1", ch=3), "ch=3 mdi G0 X1"),
])
def test_a_refused_call_says_what_its_scenario_line_says(mill, call, line):
    with pytest.raises(nck.ActionError) as typed:
        call(mill.session())
    with pytest.raises(nck.ActionError) as text:
        mill.session().action(line)
    assert (typed.value.id, str(typed.value)) == (text.value.id, str(text.value))


def test_a_spindle_override_acts_in_its_channel():
    # examples/two-channel: channel 1 has S1, S2, S3; channel 2 has no S3
    s = nck.Machine(EXAMPLES / "two-channel").session()
    s.override(spindle={"S3": 50}, ch=1)
    with pytest.raises(nck.ActionError, match="channel 2 has no spindle 'S3'"):
        s.override(spindle={"S3": 50}, ch=2)


def test_threads_sharing_a_session_take_turns(mill):
    # step() releases the GIL: four threads stepping one session and one
    # reading it take turns (they corrupted memory when they did not)
    s = mill.session(EXAMPLES / "mill" / "contour.nc")

    def stepper():
        for _ in range(100):
            s.step(200)

    def reader():
        for _ in range(400):
            s.events()
            s.state()
            assert s.cycles <= 4 * 100 * 200

    threads = [threading.Thread(target=stepper) for _ in range(4)] + [threading.Thread(target=reader)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert s.cycles == 4 * 100 * 200
