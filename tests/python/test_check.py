"""nck.check: the pre-flight lint, the very findings of `nck check --json` (issue 47 item 7)."""
import json
import subprocess

import pytest

import nck
from conftest import EXAMPLES

MILL = str(EXAMPLES / "mill")
MISTAKES = str(EXAMPLES / "mill" / "check_mistakes.nc")


def cli_check(nck_binary, *args):
    done = subprocess.run([nck_binary, "check", *args, "--json"], capture_output=True, text=True)
    return done.returncode, json.loads(done.stdout)


def test_check_gives_the_commands_json(nck_binary):
    rc, cli = cli_check(nck_binary, MILL, MISTAKES)
    found = nck.check(MILL, MISTAKES)
    assert rc == 1 and found == cli
    assert {d["id"] for d in found} >= {930002, 930004, 920005, 920022, 930003, 920044}
    assert all(d["channel"] == 1 for d in found if d.get("file", "").endswith("check_mistakes.nc"))
    # the diagnostic's one shape; a field that does not apply is left out
    assert {"id", "name", "severity", "message", "remedy", "file", "line", "channel"} <= set(found[0])
    assert set(found[0]) <= {"id", "name", "severity", "message", "remedy", "file", "line", "column", "channel"}


def test_check_of_the_machine_alone_and_of_a_good_program(nck_binary):
    rc, cli = cli_check(nck_binary, MILL)
    assert nck.check(MILL) == cli  # the machine-only warnings (70252) too
    assert not any(d["severity"] == "error" for d in nck.check(nck.Machine(MILL), [EXAMPLES / "mill" / "contour.nc"]))


def test_bad_machine_data_is_a_finding_not_an_exception(nck_binary, tmp_path):
    rc, cli = cli_check(nck_binary, str(tmp_path))
    found = nck.check(tmp_path)
    assert rc == 1 and found == cli and found[0]["severity"] == "error" and "channel" not in found[0]


def test_check_refuses_what_the_command_calls_bad_usage(tmp_path):
    with pytest.raises(nck.ProgramError) as e:
        nck.check(MILL, tmp_path / "missing.nc")
    assert e.value.id == 940202
    with pytest.raises(nck.ArgumentError) as e:
        nck.check(MILL, [MISTAKES, MISTAKES])  # the mill has one channel
    assert e.value.id == 940201
    with pytest.raises(nck.ArgumentError):
        nck.check(MILL, MISTAKES, max_wall=-1)
