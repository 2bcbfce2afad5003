"""A part program's properties checked with pytest (docs/python.md):

    PYTHONPATH=build/default/python python3 -m pytest examples/python/test_part_properties.py

Never below Z-5, done within 30 s, the spindle at speed before the first
cut, no error."""
import pathlib

import pytest

import nck

HERE = pathlib.Path(__file__).resolve().parent
MACHINE = HERE.parent / "mill"
PROGRAM = HERE / "part.nc"


@pytest.fixture(scope="module")
def run():
    return nck.Machine(MACHINE).run(PROGRAM, trace_every=1)


def test_it_runs_to_its_end_without_an_error(run):
    assert run.exit == 0 and run.errors == [], run.summary()


def test_z_never_goes_below_minus_5(run):
    assert run.trace["Z"].min() >= -5.0


def test_the_cycle_time_is_under_30_s(run):
    assert run.time_s < 30.0


def test_the_spindle_is_at_speed_before_the_first_cut(run):
    first_cut = next(b["line"] for b in nck.parse(PROGRAM) if b["modal"]["motion"] == "G1")
    cut_starts = next(e["t"] for e in run.events if e["ev"] == "block" and e["line"] == first_cut)
    at_speed = next(e["t"] for e in run.events if e["ev"] == "speed_reached" and e["spindle"] == "S1")
    assert at_speed <= cut_starts
