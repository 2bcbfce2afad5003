"""The examples in examples/python/ run (each as a user would start it)."""
import os
import subprocess
import sys

from conftest import ROOT

EXAMPLES = ROOT / "examples" / "python"


def run(*args):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, env=dict(os.environ),
                          cwd=ROOT, timeout=240)


def test_the_part_properties_pass():
    r = run("-m", "pytest", "-q", "-p", "no:cacheprovider", EXAMPLES / "test_part_properties.py")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "4 passed" in r.stdout


def test_the_session_walkthrough_runs():
    r = run(EXAMPLES / "session_walkthrough.py")
    assert r.returncode == 0, r.stderr
    assert "program end at" in r.stdout and "errors: []" in r.stdout


def test_the_acceleration_sweep_gets_slower_with_less_acceleration(tmp_path):
    r = run(EXAMPLES / "accel_sweep.py", tmp_path)
    assert r.returncode == 0, r.stderr
    rows = [line.split(",") for line in (tmp_path / "accel_sweep.csv").read_text().splitlines()[1:]]
    times = [float(t) for _, t, code in rows if code == "0"]
    assert len(times) == 3 and times[0] > times[1] > times[2], rows
