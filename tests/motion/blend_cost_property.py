#!/usr/bin/env python3
"""Blending never costs time, as a property (issue 43, item 2): a random
mill program (limits_property.py's generator: lines, arcs, fine polylines,
dwells, M functions, one #SLOPE type) runs once unblended and once with
#CONTOUR MODE [DEV PATH_DEV=..] G261 at a random tolerance; the blended run
may take at most one cycle per block longer (the program end's time from the
events).

  blend_cost_property.py NCK SOURCE_DIR [--cases N] [--seed S] [--minutes M] [--machine DIR]
                         [--slopes STEP,TRAPEZ,SIN2,HSC]

--slopes draws each program's #SLOPE type from these (default: STEP; the
jerk-limited slopes do not hold it yet: docs/performance.md, issue 43).

A program that breaks it is printed with both times, and the exit code is 1.
"""
import json
import pathlib
import random
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import limits_property  # noqa: E402  (the program generator)

DT_S = 0.001


def unblended(text):
    return "\n".join(l for l in text.splitlines() if not l.startswith("#CONTOUR") and l != "G261") + "\n"


def blended(text, path_dev):
    lines = unblended(text).splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("#SLOPE")) + 1
    lines[at:at] = [f"#CONTOUR MODE [DEV PATH_DEV={path_dev}]", "G261"]
    return "\n".join(lines) + "\n"


def end_time(nck, machine, text, work):
    (work / "p.nc").write_text(text)
    events = work / "e.jsonl"
    done = subprocess.run([nck, "run", str(machine), str(work / "p.nc"), "--events", str(events), "--max-time", "600"],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        return None
    for line in events.read_text().splitlines():
        e = json.loads(line)
        if e.get("ev") == "end":
            return e["t"]
    return None


def main():
    ap = limits_property.campaign_arguments(43)
    ap.add_argument("--slopes", default="STEP")
    a = ap.parse_args()
    slopes = a.slopes.split(",")
    machine = limits_property.campaign_machine(a)
    rng = random.Random(a.seed)
    started = time.monotonic()
    cases = 0
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        while limits_property.goes_on(a, cases, started):
            text = re.sub(r"#SLOPE \[TYPE=\w+\]", f"#SLOPE [TYPE={rng.choice(slopes)}]", limits_property.program(rng))
            path_dev = rng.choice([0.005, 0.01, 0.05, 0.2])
            plain = end_time(a.nck, machine, unblended(text), work)
            blend = end_time(a.nck, machine, blended(text, path_dev), work)
            cases += 1
            if plain is None or blend is None:
                print(f"case {cases}: a run failed\n{text}", file=sys.stderr)
                return 1
            blocks = sum(1 for l in text.splitlines() if l and l[0] in "GXYZ")
            if blend > plain + blocks * DT_S + 1e-9:
                print(f"case {cases}: blended (PATH_DEV {path_dev}) {blend:.3f} s > unblended {plain:.3f} s "
                      f"+ {blocks} cycles\n--- program\n{unblended(text)}", file=sys.stderr)
                return 1
    print(f"{cases} random programs: blending never cost more than a cycle per block "
          f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
