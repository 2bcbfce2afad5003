"""A feed override above 100 %: every surface takes 0..200 as the HLI value
and the path moves at most at 100 % (TF5200 P-CHAN-00056 at its default;
docs/decisions.md, "The feed override's range"). Issue 47 item 7."""
import json
import subprocess

import pytest

import nck
from conftest import EXAMPLES

LONG = "G1 X400 F3000\nM30\n"  # 50 mm/s


def session_velocity(mill, prog, operate):
    s = mill.session(prog)
    operate(s)
    s.step(2000)
    ch = s.state()["channels"][0]
    return ch["path_velocity_mm_s"], ch["feed_override_pct"]


def test_150_percent_moves_as_100_in_a_session_and_the_hli_keeps_150(mill, program):
    prog = program(LONG)
    full = session_velocity(mill, prog, lambda s: s.override(feed=100))
    by_call = session_velocity(mill, prog, lambda s: s.override(feed=150))
    by_line = session_velocity(mill, prog, lambda s: s.action("feed_override 150"))
    assert full[0] == pytest.approx(50.0)
    assert by_call == by_line == (full[0], 150.0)


def test_150_percent_takes_the_time_of_100_in_every_run(mill, program, nck_binary, tmp_path):
    prog = program(LONG)
    plain = mill.run(prog).time_s
    assert mill.run(prog, override=150).time_s == plain
    assert mill.run(prog, plc=["0 feed_override 150"]).time_s == plain
    plc, final = tmp_path / "fast.plc", tmp_path / "final.json"
    plc.write_text("0 feed_override 150\n")
    subprocess.run([nck_binary, "run", str(EXAMPLES / "mill"), prog, "--plc", str(plc), "--final", str(final)],
                   check=True, capture_output=True)
    assert json.loads(final.read_text())["time"] == pytest.approx(plain)


def test_above_200_is_refused_with_the_grammars_id_everywhere(mill, program):
    prog = program(LONG)
    s = mill.session(prog)
    for call in (lambda: s.override(feed=201), lambda: s.action("feed_override 201")):
        with pytest.raises(nck.ActionError) as e:
            call()
        assert e.value.id == 960003  # the grammar's own ID, not 960040 with it in the text (issue 47 item 5)
    with pytest.raises(nck.ProgramError) as e:
        mill.run(prog, override=201)
    assert e.value.id == 960003
