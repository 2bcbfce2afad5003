"""Ctrl-C during every long call of the module (issue 45's campaign): it
raises KeyboardInterrupt within a second and what the call used still
works. Each case is a child process of tests/stress/py_stress.py that
starts the call and gets SIGINT.

Before: nck.parse of an endless loop went on for 16-40 s (until the
decoder's budget), a thread waiting for a session another thread stepped
hung (over 120 s), and nck.batch waited for its running jobs (13-50 s)."""
import sys

import pytest

from conftest import ROOT

sys.path.insert(0, str(ROOT / "tests" / "stress"))
import py_stress  # noqa: E402


@pytest.mark.parametrize("kind", py_stress.CTRL_C_CASES)
def test_ctrl_c_interrupts_the_call(kind):
    r = py_stress.ctrl_c_case(kind, limit_s=60)
    assert r["outcome"] == "KeyboardInterrupt", r
    assert r["seconds"] < 1.0 and r["usable"] and r["returncode"] == 0, r
