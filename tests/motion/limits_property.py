#!/usr/bin/env python3
"""Motion safety as a property (issue 44, item 1): random programs under
random operator actions never drive an axis beyond its limits.

Each case is a random mill program (G0, G1, G2/G3, dwells, M functions,
one #SLOPE type: STEP, TRAPEZ, SIN2 or HSC, with or without PATH_DEV
blending) run with a random PLC scenario: resets, feedholds, feed override
steps, NC stop and cycle start, single step, MDI after a reset or the end,
jogs after the end. Every cycle of the trace is checked:
  |v| <= dynamik.vb_max and |a| <= dynamik.a_max of each axis.
The 6-decimal trace adds up to 2e-6 mm of rounding to a second difference
(2 mm/s^2 at 1 ms); the bound allows 3 mm/s^2 and 1e-3 mm/s. With --jerk,
a program under a jerk-limited slope (TRAPEZ, SIN2, HSC) also keeps every
axis's jerk within pi/2 a_max / tr_min (the drive's bound; SIN2's peak
is pi/2 times its mean), with 4,000 mm/s^3 for the rounding of a third
difference, up to the program's end (jogs and MDI after it are not under
its #SLOPE).

  limits_property.py NCK SOURCE_DIR [--cases N] [--seed S] [--minutes M] [--machine DIR]

--machine runs them on another machine folder than examples/mill (e.g.
bench/machines/equal-limits, where the feed accelerations equal a_max and
a kink has no acceleration to spare above the path's).

A violation prints the program, the scenario and the cycle, and exits 1.
"""
import argparse
import json
import math
import pathlib
import random
import re
import subprocess
import sys
import tempfile
import time

AXES = ("X", "Y", "Z")
DT_S = 0.001
A_TOL_MM_S2 = 3.0
V_TOL_MM_S = 1e-3
J_TOL_MM_S3 = 4000.0


def axis_limits(machine):
    """(vb_max mm/s, a_max mm/s^2, jerk bound mm/s^3) of X, Y, Z from the example's axis lists."""
    limits = {}
    for axis in AXES:
        text = (machine / f"{axis.lower()}.lis").read_text()
        vb = re.search(r"getriebe\[0\]\.dynamik\.vb_max\s+(\d+)", text)
        a = re.search(r"getriebe\[0\]\.dynamik\.a_max\s+(\d+)", text)
        tr_min = re.search(r"getriebe\[0\]\.dynamik\.tr_min\s+(\d+)", text)
        tr_min_s = int(tr_min.group(1)) * 1e-6 if tr_min else 0.01  # P-AXIS-00201 default 10 ms
        a_max = float(a.group(1))
        limits[axis] = (int(vb.group(1)) / 1000.0, a_max, math.pi / 2 * a_max / tr_min_s)
    return limits


def point(rng):
    return round(rng.uniform(-80, 80), 3), round(rng.uniform(-80, 80), 3), round(rng.uniform(-40, 10), 3)


def program(rng):
    slope = rng.choice(["STEP", "TRAPEZ", "SIN2", "HSC"])
    lines = [f"N1 G90 G17 F{rng.choice([600, 3000, 9000, 20000])}", f"#SLOPE [TYPE={slope}]"]
    if rng.random() < 0.5:
        lines.append("#CONTOUR MODE [DEV PATH_DEV=0.05]")
        lines.append("G261")
    here = (0.0, 0.0, 0.0)
    for _ in range(rng.randint(5, 40)):
        roll = rng.random()
        if roll < 0.15:
            here = point(rng)
            lines.append(f"G0 X{here[0]} Y{here[1]} Z{here[2]}")
        elif roll < 0.25:
            # an arc in the plane about a centre beside the start point
            cx, cy = here[0] + rng.uniform(-20, 20), here[1] + rng.uniform(-20, 20)
            r = math.hypot(here[0] - cx, here[1] - cy)
            angle = math.atan2(here[1] - cy, here[0] - cx) + rng.uniform(0.3, 3.0)
            end = (round(cx + r * math.cos(angle), 4), round(cy + r * math.sin(angle), 4), here[2])
            lines.append(f"G3 X{end[0]} Y{end[1]} I{round(cx - here[0], 4)} J{round(cy - here[1], 4)}")
            here = end
        elif roll < 0.30:
            lines.append(rng.choice(["G4 X0.05", "M8", "M9", "P1 = 2"]))
        elif roll < 0.38:
            lines.append(f"F{rng.choice([300, 1200, 6000, 15000])}")
        elif roll < 0.48:
            here = fine_polyline(rng, here, lines)
        else:
            # short and long lines, mostly small kinks, sometimes a reversal
            step = rng.choice([0.2, 1, 5, 30])
            here = tuple(round(min(max(c + rng.uniform(-step, step), -90), 90), 3) for c in here)
            here = (here[0], here[1], min(here[2], 10))
            lines.append(f"G1 X{here[0]} Y{here[1]} Z{here[2]}")
    lines.append("M30")
    return "\n".join(lines) + "\n"


def fine_polyline(rng, here, lines):
    """Chords of 0.1 to 2 mm turning by up to 6 degrees each (a CAM program's
    fine segments, whose kinks are passed at speed near the kink rule's
    limit), in the XY plane or climbing in Z; returns the last point."""
    step = rng.choice([0.1, 0.25, 0.5, 2.0])
    heading, climb = rng.uniform(0, 2 * math.pi), rng.choice([0.0, 0.2])
    for _ in range(rng.randint(5, 30)):
        heading += math.radians(rng.uniform(-6, 6))
        x = min(max(here[0] + step * math.cos(heading), -90), 90)
        y = min(max(here[1] + step * math.sin(heading), -90), 90)
        here = (round(x, 4), round(y, 4), round(min(here[2] + climb * step * rng.uniform(-1, 1), 10), 4))
        lines.append(f"G1 X{here[0]} Y{here[1]} Z{here[2]}")
    return here


def scenario(rng):
    actions = []
    t = 0.0
    for _ in range(rng.randint(1, 8)):
        t += rng.uniform(0.05, 1.5)
        kind = rng.random()
        if kind < 0.2:
            actions.append(f"{t:.3f} reset")
            actions.append(f"{t + 0.5:.3f} mdi G1 X{rng.uniform(-50, 50):.3f} F{rng.choice([600, 6000])}")
        elif kind < 0.4:
            actions.append(f"{t:.3f} feedhold on")
            actions.append(f"{t + rng.uniform(0.01, 0.5):.3f} feedhold off")
        elif kind < 0.6:
            actions.append(f"{t:.3f} feed_override {rng.choice([0, 10, 50, 100, 120, 200])}")
        elif kind < 0.7:
            actions.append(f"{t:.3f} stop")
        elif kind < 0.8:
            actions.append(f"{t:.3f} single_step {rng.choice(['on', 'off'])}")
        elif kind < 0.9:
            actions.append(f"{t:.3f} rapid_override {rng.choice([5, 50, 100])}")
        else:
            axis = rng.choice(AXES)
            actions.append(f"@ended+0.01 jog {axis} {rng.choice(['+', '-'])} {rng.choice([600, 3000])}")
            actions.append(f"@ended+0.3 jog {axis} stop")
    return "\n".join(actions) + "\n"


def trace_rows(path):
    lines = path.read_text().splitlines()
    header = lines[0].split(",")
    cols = {name: header.index(name) for name in ("t",) + AXES}
    return [[float(cells[cols[n]]) for n in ("t",) + AXES] for cells in (l.split(",") for l in lines[1:])]


def violation(rows, limits, jerk_until_s):
    """The first cycle that breaks a limit, as text, or None (the jerk only before jerk_until_s)."""
    for i in range(1, len(rows)):
        for k, axis in enumerate(AXES, start=1):
            vb, a_max, j_max = limits[axis]
            v = (rows[i][k] - rows[i - 1][k]) / DT_S
            if abs(v) > vb + V_TOL_MM_S:
                return f"t={rows[i][0]:.3f} {axis} v={v:.3f} mm/s > {vb}"
            if i >= 2:
                a = (rows[i][k] - 2 * rows[i - 1][k] + rows[i - 2][k]) / DT_S**2
                if abs(a) > a_max + A_TOL_MM_S2:
                    return f"t={rows[i][0]:.3f} {axis} a={a:.1f} mm/s^2 > {a_max}"
            if i >= 3 and rows[i][0] < jerk_until_s:
                j = (rows[i][k] - 3 * rows[i - 1][k] + 3 * rows[i - 2][k] - rows[i - 3][k]) / DT_S**3
                if abs(j) > j_max + J_TOL_MM_S3:
                    return f"t={rows[i][0]:.3f} {axis} j={j:.0f} mm/s^3 > {j_max:.0f}"
    return None


def check_one(nck, machine, limits, prog_text, plc_text, work, jerk):
    (work / "p.nc").write_text(prog_text)
    (work / "s.plc").write_text(plc_text)
    trace, events = work / "t.csv", work / "e.jsonl"
    done = subprocess.run([nck, "run", str(machine), str(work / "p.nc"), "--plc", str(work / "s.plc"),
                           "--trace", str(trace), "--events", str(events), "--max-time", "120"],
                          capture_output=True, text=True, timeout=600)
    if done.returncode not in (0, 1):
        return f"exit {done.returncode}: {done.stderr[-500:]}", 0
    rows = trace_rows(trace)
    jerk_until_s = program_end_s(events) if jerk and "TYPE=STEP" not in prog_text else -1.0
    return violation(rows, limits, jerk_until_s), len(rows)


def program_end_s(events):
    """When the program ended (its first `end` event), or never."""
    for line in events.read_text().splitlines():
        e = json.loads(line)
        if e.get("ev") == "end":
            return e["t"]
    return math.inf


def campaign_arguments(default_seed):
    """The arguments every random campaign here takes (NCK SOURCE --cases
    --seed --minutes --machine); the caller adds its own and parses."""
    ap = argparse.ArgumentParser()
    ap.add_argument("nck")
    ap.add_argument("source")
    ap.add_argument("--cases", type=int, default=30)
    ap.add_argument("--seed", type=int, default=default_seed)
    ap.add_argument("--minutes", type=float, default=0)
    ap.add_argument("--machine", help="machine folder (default: SOURCE/examples/mill)")
    return ap


def campaign_machine(a):
    return pathlib.Path(a.machine) if a.machine else pathlib.Path(a.source) / "examples" / "mill"


def goes_on(a, cases, started):
    """--cases cases, or with --minutes until that time has passed."""
    return cases < a.cases if a.minutes == 0 else time.monotonic() - started < a.minutes * 60


def main():
    ap = campaign_arguments(44)
    ap.add_argument("--jerk", action="store_true", help="check the jerk under jerk-limited slopes too")
    a = ap.parse_args()
    machine = campaign_machine(a)
    limits = axis_limits(machine)
    rng = random.Random(a.seed)
    started = time.monotonic()
    cases = cycles = 0
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        while goes_on(a, cases, started):
            prog_text, plc_text = program(rng), scenario(rng)
            bad, n = check_one(a.nck, machine, limits, prog_text, plc_text, work, a.jerk)
            cases += 1
            cycles += n
            if bad:
                print(f"case {cases}: {bad}\n--- program\n{prog_text}--- scenario\n{plc_text}", file=sys.stderr)
                return 1
    print(f"{cases} random programs and scenarios, {cycles} cycles checked, 0 violations "
          f"({time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
