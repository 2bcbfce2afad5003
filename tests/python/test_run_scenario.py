"""Machine.run(override=, feedhold=, plc=[lines]) and the trace's path.v (issue 47 item 7)."""
import subprocess

import numpy as np
import pytest

import nck
from conftest import EXAMPLES

LONG = "G1 X400 F3000\nM30\n"  # 50 mm/s for 8 s


def test_override_is_the_scenario_line_it_means(mill, program, tmp_path):
    prog = program(LONG)
    plc = tmp_path / "half.plc"
    plc.write_text("0 feed_override 50\n")
    by_file, by_option = mill.run(prog, plc=plc), mill.run(prog, override=50)
    assert by_option.time_s == by_file.time_s and by_option.events == by_file.events
    assert by_option.time_s == pytest.approx(2 * mill.run(prog).time_s, rel=0.01)
    assert mill.run(prog, override={"feed": 50}).time_s == by_option.time_s


def test_a_plc_list_needs_no_file(mill, program, tmp_path):
    prog = program(LONG)
    lines = ["0.5 feedhold on", "1.5 feedhold off   # a second's hold"]
    plc = tmp_path / "hold.plc"
    plc.write_text("\n".join(lines) + "\n")
    by_file, by_list = mill.run(prog, plc=plc), mill.run(prog, plc=lines)
    assert by_list.time_s == by_file.time_s and by_list.events == by_file.events
    assert mill.run(prog, feedhold=(0.5, 1.5)).time_s == by_file.time_s
    assert by_list.time_s > mill.run(prog).time_s + 0.9


def test_the_plcs_own_line_acts_after_the_options_at_the_same_time(mill, program, tmp_path):
    prog = program(LONG)
    plc = tmp_path / "eighty.plc"
    plc.write_text("0 feed_override 80\n")
    both = mill.run(prog, plc=plc, override=50, feedhold=[(1, 2), (3, 3.5)])
    alone = mill.run(prog, plc=["0 feed_override 80", "1 feedhold on", "2 feedhold off", "3 feedhold on",
                                "3.5 feedhold off"])
    assert both.time_s == alone.time_s


def test_bad_scenario_arguments_raise_with_their_ids(mill, program):
    prog = program(LONG)
    with pytest.raises(nck.ProgramError) as e:
        mill.run(prog, plc=["0 feed_override 50", "1 no_such_action"])
    assert e.value.id == 960002 and e.value.file == "<plc>" and e.value.line == 2
    with pytest.raises(nck.ProgramError) as e:
        mill.run(prog, override=250)  # the grammar's range, as in a file
    assert e.value.id == 960003 and e.value.file == "<override/feedhold>"
    with pytest.raises(nck.ArgumentError):
        mill.run(prog, feedhold=(2, 1))
    with pytest.raises(nck.ArgumentError):
        mill.run(prog, plc=["0 feedhold on\n1 feedhold off"])  # one line per str
    with pytest.raises(nck.ArgumentError):
        mill.run(prog, override={"feedrate": 50})
    with pytest.raises(nck.ProgramError) as e:
        mill.run(prog, override={"S9": 50})  # a spindle name, but none of the machine's
    assert e.value.id == 960007
    with pytest.raises(nck.ArgumentError) as e:
        mill.run(prog, trace_every=10, trace_columns="path.x")
    assert e.value.id == 940201


def test_the_trace_has_the_path_velocity(mill, program, nck_binary, tmp_path):
    prog = program(LONG)
    r = mill.run(prog, trace_every=10)
    v = r.trace["path.v"]
    assert v.max() == pytest.approx(50.0) and 0 < v[0] < 5  # the first row: after the first cycle
    assert "path.v" not in mill.run(prog, trace_every=10, trace_columns=None).trace
    r3 = mill.run(prog, trace_every=10, trace_columns=["path.v", "path.a"])
    assert list(r3.trace)[-2:] == ["path.v", "path.a"] and np.array_equal(r3.trace["path.v"], v)
    csv = tmp_path / "t.csv"
    subprocess.run([nck_binary, "run", str(EXAMPLES / "mill"), prog, "--trace", str(csv), "--trace-every", "10",
                    "--trace-columns", "path.v"], check=True, capture_output=True)
    header = csv.read_text().splitlines()[0].split(",")
    assert header == list(r.trace)
    assert np.allclose(np.loadtxt(csv, delimiter=",", skiprows=1)[:, -1], v, atol=1e-6)
