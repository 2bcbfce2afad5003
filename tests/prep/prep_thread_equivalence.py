#!/usr/bin/env python3
"""--prep-thread gives the plain run's outputs on random programs with tool
radius compensation (issue 45, item 2).

Each program mixes G41/G42 selections, side and radius changes, lines and
arcs, blocks that repeat where the plane axes stand (zero length) or move
them by a few tenths of a micrometre (near zero), blocks without plane
motion (Z, M8/M9, assignments), local subroutine calls and G40. Many end in
a compensation error (a bottleneck, 90011): that is fine as long as both
runs end the same. The events, the trace and the final state of both runs
must be equal byte for byte.

  prep_thread_equivalence.py NCK SOURCE_DIR [--programs N] [--seed S] [--minutes M]

--minutes runs programs until that much wall time has passed (the long
campaign of docs/robustness.md); it prints the figures at the end.
"""
import argparse
import math
import pathlib
import random
import subprocess
import sys
import tempfile
import time


def step(rng, here, heading):
    """The next end point of a gently turning walk: mostly a real move,
    sometimes none (zero length) or a few tenths of a micrometre."""
    kind = rng.random()
    if kind < 0.12:
        return here, heading
    if kind < 0.18:
        return (round(here[0] + 3e-4 * math.cos(heading), 7), round(here[1] + 3e-4 * math.sin(heading), 7)), heading
    heading += math.radians(rng.uniform(-50, 50))
    length = rng.uniform(6, 25)
    return (round(here[0] + length * math.cos(heading), 3), round(here[1] + length * math.sin(heading), 3)), heading


def motion(rng, here, heading):
    end, heading = step(rng, here, heading)
    chord = math.dist(here, end)
    if chord > 1 and rng.random() < 0.25:
        # a flat arc (radius at least twice the chord): never inside the tool
        radius = round(chord * rng.uniform(2, 5), 3)
        return end, heading, f"{rng.choice(['G2', 'G3'])} X{end[0]} Y{end[1]} R{radius}"
    return end, heading, f"G1 X{end[0]} Y{end[1]}"


def program(rng):
    lines = ["N1 G17 G90 F2000 D1 P1 = 0", "N2 G0 X0 Y0 Z5"]
    here, heading = (0.0, 0.0), 0.0
    side = None
    for _ in range(rng.randint(10, 60)):
        roll = rng.random()
        if roll < 0.08 or (side is None and roll < 0.3):
            side = rng.choice(["G41", "G42"])
            here, heading, text = motion(rng, here, heading)
            lines.append(f"{side} {text.replace('G2', 'G1').replace('G3', 'G1').split(' R')[0]}")
        elif roll < 0.12 and side:
            here = (here[0] + 10 * math.cos(heading), here[1] + 10 * math.sin(heading))
            here = (round(here[0], 3), round(here[1], 3))
            lines.append(f"G40 G1 X{here[0]} Y{here[1]}")
            side = None
        elif roll < 0.15:
            here = (round(here[0] + 8 * math.cos(heading), 3), round(here[1] + 8 * math.sin(heading), 3))
            lines.append(f"D{rng.choice([1, 2])} G1 X{here[0]} Y{here[1]}")
        elif roll < 0.24:
            lines.append(rng.choice(["Z2", "M8", "M9", "P1 = P1 + 1", "G1 Z-1"]))
        elif roll < 0.29:
            # a run of repeated end points: more than 8 under compensation is 90011
            lines += [f"X{here[0]} Y{here[1]}"] * rng.randint(2, 12)
        elif roll < 0.32:
            lines.append("LL STEP")  # 8 mm on in X, incrementally
            here, heading = (round(here[0] + 8, 3), here[1]), 0.0
        else:
            here, heading, text = motion(rng, here, heading)
            lines.append(text)
    lines.append("G40 G1 X200 Y200")
    lines.append("M30")
    sub = ["%L STEP", "G91 G1 X8", "G90", "M17"]
    return "\n".join(sub + ["%main"] + lines) + "\n"


def outputs(nck, machine, prog, out, threaded):
    out.mkdir(exist_ok=True)
    cmd = [nck, "run", str(machine), str(prog), "--events", str(out / "events.jsonl"),
           "--trace", str(out / "trace.csv"), "--final", str(out / "final.json"), "--max-time", "600"]
    if threaded:
        cmd.append("--prep-thread")
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    files = {name: (out / name).read_bytes() for name in ("events.jsonl", "trace.csv", "final.json")}
    return done.returncode, files


def check_one(nck, machine, text, work):
    prog = work / "prog.nc"
    prog.write_text(text)
    plain = outputs(nck, machine, prog, work / "plain", False)
    threaded = outputs(nck, machine, prog, work / "threaded", True)
    if plain == threaded:
        return None
    differing = [name for name in plain[1] if plain[1][name] != threaded[1][name]]
    return f"exit {plain[0]} vs {threaded[0]}; differing: {differing}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("nck")
    ap.add_argument("source")
    ap.add_argument("--programs", type=int, default=40)
    ap.add_argument("--seed", type=int, default=45)
    ap.add_argument("--minutes", type=float, default=0)
    a = ap.parse_args()
    machine = pathlib.Path(a.source) / "examples" / "mill"
    rng = random.Random(a.seed)
    started = time.monotonic()
    checked = 0
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        while (checked < a.programs) if a.minutes == 0 else (time.monotonic() - started < a.minutes * 60):
            text = program(rng)
            failure = check_one(a.nck, machine, text, work)
            checked += 1
            if failure:
                (pathlib.Path(tmp).parent / "prep_thread_failure.nc").write_text(text)
                print(f"program {checked}: {failure}\n{text}", file=sys.stderr)
                return 1
    print(f"{checked} random TRC programs: --prep-thread outputs equal the plain run's "
          f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
