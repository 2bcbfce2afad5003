"""The events kept in memory (issue 45, item 10): a compact form (JSON lines
and 32-byte records, numpy records on demand) bounded by max_events_mb; a
run ends at the bound with an ID, a session drops its oldest (a ring)."""
import subprocess
import sys

import numpy as np
import pytest

import nck
from conftest import EXAMPLES

BOUND_ERROR, DROPPED_WARNING = 940204, 940205


@pytest.fixture(scope="module")
def many_blocks(tmp_path_factory):
    """3,000 short blocks: a block event each."""
    p = tmp_path_factory.mktemp("prog") / "many.nc"
    p.write_text("G90 G1 F60000\n" + "".join(f"N{i} X{i % 2}.0 Y{i % 3 * 0.5}\n" for i in range(10, 3010)) + "M30\n")
    return p


def test_the_event_memory_limit_ends_the_run_with_an_id(mill, many_blocks):
    full = mill.run(many_blocks)
    r = mill.run(many_blocks, max_events_mb=0.1)
    assert full.exit == 0 and r.exit == 1 and r.end == "max_events"
    assert [e["id"] for e in r.errors] == [BOUND_ERROR] and "104857 bytes" in r.errors[0]["msg"]
    # the events so far, then the channel's closing state and end events (past the bound)
    assert r.events[:-2] == full.events[:len(r.events) - 2]
    assert [(e["ev"], e["reason"]) for e in r.events[-2:]] == [("state", "max_events"), ("end", "max_events")]
    assert r.event_bytes <= 0.1 * 1024 * 1024 + 300 < full.event_bytes
    assert r.final["end"] == "max_events"


def test_events_take_about_a_hundred_bytes_each(mill, many_blocks):
    r = mill.run(many_blocks)
    assert len(r.events) > 3000
    assert r.event_bytes / len(r.events) < 200  # a JSON object each took ~640 bytes
    assert r.event_records.itemsize == 22


def test_the_records_are_the_events_heads(mill):
    r = mill.run(EXAMPLES / "mill" / "spindle.nc", plc=EXAMPLES / "mill" / "spindle.plc")
    rec = r.event_records
    assert len(rec) == len(r.events) and rec.dtype.names == ("t", "ch", "ev", "line", "n")
    for row, e in zip(rec, r.events):
        assert (row["t"], row["ch"], nck.EVENT_KINDS[row["ev"]]) == (e["t"], e["ch"], e["ev"])
        # the head's block, which some kinds (plc_out ...) do not write
        assert row["line"] == e.get("line", row["line"])
        assert row["n"] == (-1 if e.get("n", row["n"]) is None else e.get("n", row["n"]))
    blocks = np.nonzero(rec["ev"] == nck.EVENT_KINDS.index("block"))[0]
    assert len(blocks) == sum(e["ev"] == "block" for e in r.events)
    assert r.event(int(blocks[0])) == r.events[blocks[0]] and r.event(-1) == r.events[-1]
    with pytest.raises(nck.ArgumentError):
        r.event(len(rec))


def test_no_events_kept_is_an_empty_table(mill):
    r = mill.run(EXAMPLES / "mill" / "contour.nc", events=False)
    assert r.events == [] and len(r.event_records) == 0 and r.event_bytes == 0


def test_a_session_keeps_the_newest_events_and_says_it_dropped_some(mill, many_blocks):
    s = mill.session(many_blocks, max_events_mb=0.02)
    assert s.run_until(block=2500)  # matched although older events went meanwhile
    events = s.events()
    assert 0 < len(events) < 0.02 * 1024 * 1024 / 80  # no more than the bound holds
    assert any(e["ev"] == "warning" and e["id"] == DROPPED_WARNING for e in events)
    assert [e["n"] for e in events if e["ev"] == "block"][-1] == 2500  # the newest are kept
    assert s.run_until(event="end") and "end" in [e["ev"] for e in s.events()]


def test_bad_bounds_raise_argument_error(mill, many_blocks):
    for bad in (0, -1, float("inf"), float("nan"), "10"):
        with pytest.raises(nck.ArgumentError):
            mill.run(many_blocks, max_events_mb=bad)
        with pytest.raises(nck.ArgumentError):
            mill.session(many_blocks, max_events_mb=bad)


PEAK_RSS = """
import resource, sys
import nck
r = nck.Machine(sys.argv[1]).run(sys.argv[2], events=sys.argv[3] == "1")
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def test_a_run_of_50000_events_holds_them_in_a_few_mb(tmp_path):
    # peak RSS with events minus without: 34 MB before (a JSON object and a
    # typed copy per event), about 8 MB now
    prog = tmp_path / "50k.nc"
    prog.write_text("G90 G1 F600000\n" + "".join(f"N{i} X{i % 2}.0\n" for i in range(10, 50010)) + "M30\n")
    peak_kb = [int(subprocess.run([sys.executable, "-c", PEAK_RSS, str(EXAMPLES / "mill"), str(prog), keep],
                                  capture_output=True, text=True, check=True).stdout) for keep in ("1", "0")]
    assert (peak_kb[0] - peak_kb[1]) / 1024 < 16, peak_kb
