"""The short form of tests/stress/py_stress.py (issue 45's campaign): threads
sharing a session, a run, a machine and batches end with nck's exceptions
or none, never a crash or a hang; 100 runs of a mix in one process reach an
RSS plateau. (Ctrl-C: test_interrupt.py; the long form's figures:
docs/robustness.md.)"""
import os
import sys

import pytest
from conftest import ROOT

sys.path.insert(0, str(ROOT / "tests" / "stress"))
import py_stress  # noqa: E402


class Args:
    threads, rounds, runs, slow_cases = 4, 100, 100, False


def test_threads_share_every_object_without_a_crash():
    r = py_stress.run_part("threads", Args)
    assert r["returncode"] == 0, r  # a crash would be a signal here
    res = r["result"]
    session = res["session"]
    assert session["escaped"] == [] and session["calls"] == Args.threads * Args.rounds
    assert set(session["refused"]) <= set(py_stress.SESSION_ERRORS)
    assert res["run"] == {"escaped": [], "distinct_results": 1}
    assert res["machine"] == {"escaped": [], "all_equal": True}
    assert res["batch"] == {"escaped": [], "all_equal": True}
    assert res["reentered"]["busy"] > 0


# ASan's quarantine holds freed memory back up to its size (256 MB), so RSS
# under it says nothing about nck: scripts/test.sh's plain leg runs this one.
UNDER_ASAN = "libasan" in os.environ.get("LD_PRELOAD", "")


@pytest.mark.skipif(UNDER_ASAN, reason="RSS under ASan's quarantine; the plain leg of scripts/test.sh measures it")
def test_many_runs_in_one_process_reach_a_plateau():
    r = py_stress.run_part("runs", Args)
    assert r["returncode"] == 0, r
    res = r["result"]
    assert len(res["rss_samples_mb"]) == 10
    assert res["rss_growth_second_half_mb"] < 8, res
