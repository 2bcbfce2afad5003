#!/usr/bin/env python3
"""The feed-section ratio of a program on a machine (issue 43's measure):
the time from the start of the first feed block to the start of the block
after the last one, read from `nck run`'s block events, divided by its
ideal (each feed block's length / its programmed feed; arcs by I/J). Feed
blocks are G1/G2/G3 blocks at half the program's highest feed or more, so
a slow plunge before the cut and the rapids, spindle run-up and final M5
after it stay out.

usage: feed_ratio.py NCK MACHINE PROGRAM [--slope STEP|TRAPEZ|SIN2|HSC] [--path-dev MM]
The mode lines (#SLOPE, #CONTOUR MODE + G261) are put in front of the
program, in a copy under a temporary folder; prints one line: the ratio,
the time, the ideal and the number of feed blocks."""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

WORD = re.compile(r"([A-Z])\s*(-?[0-9.]+)")


def feed_blocks(lines):
    """(line number, length mm, feed mm/min) of every G1/G2/G3 block, in order."""
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    motion, feed, absolute, out = 0, 0.0, True, []
    for number, text in enumerate(lines, 1):
        text = text.split(";")[0].upper()
        if text.startswith("#"):
            continue
        words = WORD.findall(text)
        for letter, value in words:
            if letter == "G" and value in ("0", "1", "2", "3", "00", "01", "02", "03"):
                motion = int(float(value))
            if letter == "G" and value in ("90", "91"):
                absolute = value == "90"
            if letter == "F":
                feed = float(value)
        given = {k: float(v) for k, v in words if k in "XYZIJ"}
        if not any(k in given for k in "XYZ"):
            continue
        end = {k: (given.get(k, pos[k]) if absolute else pos[k] + given.get(k, 0.0)) for k in pos}
        if motion in (2, 3):
            cx, cy = pos["X"] + given.get("I", 0.0), pos["Y"] + given.get("J", 0.0)
            r = math.hypot(pos["X"] - cx, pos["Y"] - cy)
            a0 = math.atan2(pos["Y"] - cy, pos["X"] - cx)
            a1 = math.atan2(end["Y"] - cy, end["X"] - cx)
            sweep = (a0 - a1) if motion == 2 else (a1 - a0)
            sweep %= 2 * math.pi
            if sweep == 0:
                sweep = 2 * math.pi
            length = math.hypot(r * sweep, end["Z"] - pos["Z"])
        else:
            length = math.dist([pos[k] for k in "XYZ"], [end[k] for k in "XYZ"])
        if motion in (1, 2, 3) and length > 0:
            out.append((number, length, feed))
        pos = end
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("nck")
    ap.add_argument("machine")
    ap.add_argument("program")
    ap.add_argument("--slope", choices=["STEP", "TRAPEZ", "SIN2", "HSC"])
    ap.add_argument("--path-dev", type=float)
    args = ap.parse_args()
    head = []
    if args.slope:
        head.append(f"#SLOPE [TYPE={args.slope}]")
    if args.path_dev:
        head += [f"#CONTOUR MODE [DEV PATH_DEV={args.path_dev}]", "G261"]
    lines = head + open(args.program).read().splitlines()
    with tempfile.TemporaryDirectory() as tmp:
        program = os.path.join(tmp, "program.nc")
        events = os.path.join(tmp, "events.jsonl")
        open(program, "w").write("\n".join(lines) + "\n")
        run = subprocess.run([args.nck, "run", "--no-progress", "--events", events, args.machine, program],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"nck run failed ({run.returncode}): {run.stderr.strip()}")
        starts = {}
        for line in open(events):
            e = json.loads(line)
            if e.get("ev") == "block" and e.get("ch", 1) == 1:
                starts.setdefault(e["line"], e["t"])
    blocks = feed_blocks(lines)
    top = max(f for _, _, f in blocks)
    cut = [b for b in blocks if b[2] >= top / 2]
    first, last = cut[0][0], cut[-1][0]
    after = min((n for n in starts if n > last), default=None)
    if first not in starts or after is None:
        sys.exit("the feed section's first block or the block after it has no block event")
    time_s = starts[after] - starts[first]
    ideal_s = sum(length / (feed / 60.0) for _, length, feed in cut)
    print(f"ratio {time_s / ideal_s:.4f}  time {time_s:.3f} s  ideal {ideal_s:.3f} s  feed blocks {len(cut)}")


if __name__ == "__main__":
    main()
