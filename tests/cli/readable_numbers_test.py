#!/usr/bin/env python3
"""Numbers as a person reads them in nck run's JSON outputs (issue 48 item 4).

  readable_numbers_test.py NCK SOURCE_DIR

Runs every example of tests/golden/examples.txt but the common program and
checks every number of the events file and the final state: at most six
decimals (1e-6, as the trace), no -0 and no noise such as
23.47000000000009 or a lost time of -4.4e-16. The trace is not checked: its columns are
fixed six decimals (docs/outputs.md). Exit 1 on any failed check.
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

NCK, SRC = sys.argv[1], Path(sys.argv[2])
failures = 0


def check(name, cond, detail=""):
    global failures
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f": {detail}"))
    failures += 0 if cond else 1


def decimals(x):
    """Decimals of the shortest representation; noise shows as many (or an exponent)."""
    text = repr(float(x))
    if "e" in text:
        mantissa, exponent = text.split("e")
        frac = mantissa.split(".")[1] if "." in mantissa else ""
        return max(0, len(frac.rstrip("0")) - int(exponent))
    return len(text.split(".")[1].rstrip("0"))


def noisy(doc, path=""):
    """(path, value) of every float with more than six decimals, or -0."""
    if isinstance(doc, dict):
        for k, v in doc.items():
            yield from noisy(v, f"{path}.{k}")
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            yield from noisy(v, f"{path}[{i}]")
    elif isinstance(doc, float):
        if decimals(doc) > 6 or (doc == 0 and str(doc).startswith("-")):
            yield path, doc


def examples():
    for line in (SRC / "tests/golden/examples.txt").read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        name, machine, programs, options = (f.strip() for f in line.split("|"))
        if not programs.startswith("common:"):
            yield name, machine, programs.split(), options.split()


for name, machine, programs, options in examples():
    with tempfile.TemporaryDirectory() as d:
        events, final = Path(d) / "e.jsonl", Path(d) / "f.json"
        p = subprocess.run([NCK, "run", str(SRC / machine), *(str(SRC / x) for x in programs),
                            *[str(SRC / o) if o.startswith("examples/") else o for o in options],
                            "--events", str(events), "--final", str(final), "--no-progress"],
                           capture_output=True, text=True, timeout=120, cwd=SRC)
        docs = [json.loads(x) for x in events.read_text().splitlines() if x] + [json.loads(final.read_text())]
        bad = [hit for doc in docs for hit in noisy(doc)]
        check(f"{name}: ran", p.returncode in (0, 1), p.stderr[-400:])
        check(f"{name}: no noise digits in the events and the final state", not bad, str(bad[:5]))

# The rounding itself: the speeds a coupled spindle reaches are real
# numbers, written at 1e-6 rpm (before: 721.1354352195448).
with tempfile.TemporaryDirectory() as d:
    events = Path(d) / "e.jsonl"
    subprocess.run([NCK, "run", str(SRC / "examples/twin-spindle"), str(SRC / "examples/twin-spindle/twin.nc"),
                    "--events", str(events), "--no-progress"], capture_output=True, timeout=120)
    lines = [json.loads(x) for x in events.read_text().splitlines() if x]
    reached = [e["rpm"] for e in lines if e["ev"] == "speed_reached"]
    check("twin: speed_reached at 1e-6 rpm", 721.135435 in reached and -1080.000072 in reached, str(reached))

sys.exit(1 if failures else 0)
