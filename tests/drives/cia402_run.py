#!/usr/bin/env python3
"""`nck run` on examples/mill-cia402 (issue 46, tests b and bad input):
the program waits for the CiA 402 drives (wait / wait_end drive_enable) and
runs to M30; a fault injected by the scenario is 940501 naming Y and the
other axes brake (X's speed falls by at most a_max per cycle in the trace);
a drive that never enables is 940500 naming Z, not a hang; spindle S1's
drive follows the spindle through its modes (test c): velocity, homing for
G74, velocity for M3, position for M19, velocity again; G74 of path axes
on DRIVE_CONTROLLED drives (home.nc): each drive homes in mode 6 while the
block waits (wait homing), its position is the axis's, the axis ends at
pos_refpkt (0) and the set point never moves faster than the axis may
except where the reference is taken."""
import csv, json, os, subprocess, sys, tempfile

nck, root = sys.argv[1], sys.argv[2]
ex = os.path.join(root, "examples/mill-cia402")
failures = []


def run(plc=None, program="enable.nc"):
    d = tempfile.mkdtemp()
    ev, tr = os.path.join(d, "ev.jsonl"), os.path.join(d, "tr.csv")
    cmd = [nck, "run", ex, os.path.join(ex, program), "--events", ev, "--trace", tr]
    if plc:
        cmd += ["--plc", os.path.join(ex, plc)]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    events = [json.loads(l) for l in open(ev)]
    rows = list(csv.DictReader(open(tr)))
    return p.returncode, events, rows


def check(cond, what):
    if not cond:
        failures.append(what)


rc, events, _ = run()
check(rc == 0, f"enable.nc: exit {rc}")
waits = [e for e in events if e["ev"] in ("wait", "wait_end") and e.get("reason") == "drive_enable"]
check([e["ev"] for e in waits] == ["wait", "wait_end"], f"enable.nc: drive_enable waits {waits}")
check(not [e for e in events if e["ev"] == "error"], "enable.nc: no error")

rc, events, rows = run("fault.plc")
errors = [e for e in events if e["ev"] == "error"]
check(rc != 0, "fault.plc: nonzero exit")
check(len(errors) == 1 and errors[0]["id"] == 940501 and errors[0].get("axis") == "Y",
      f"fault.plc: one 940501 naming Y, got {errors}")
# X brakes: its speed changes by at most a_max * T per cycle (x.lis: a_max 3000 mm/s^2; 1 ms cycle).
xcol = next(k for k in rows[0] if k.strip().upper().startswith("X"))
xs = [float(r[xcol]) for r in rows]
vs = [(b - a) / 0.001 for a, b in zip(xs, xs[1:])]
dv = max(abs(b - a) for a, b in zip(vs, vs[1:]))
check(dv / 0.001 <= 3000 * 1.05, f"fault.plc: X's acceleration {dv / 0.001:.0f} mm/s^2: not braked within limits")
check(abs(vs[-1]) < 1e-6, "fault.plc: X stands at the end")

rc, events, _ = run("never_enables.plc")
errors = [e for e in events if e["ev"] == "error"]
check(len(errors) == 1 and errors[0]["id"] == 940500 and errors[0].get("axis") == "Z",
      f"never_enables.plc: one 940500 naming Z, got {errors}")

rc, events, _ = run(program="spindle_modes.nc")
check(rc == 0, f"spindle_modes.nc: exit {rc}")
modes = [(e["mode"], e["opmode"]) for e in events if e["ev"] == "drive" and e["axis"] == "S1"]
check(modes == [("csv", 9), ("homing", 6), ("csv", 9), ("csp", 8), ("csv", 9)],
      f"spindle_modes.nc: S1's drive modes {modes}")
# Each mode change comes after the spindle's own: homing with G74, 8 with M19, 9 with M3.
spindle = [(e["t"], e["mode"]) for e in events if e["ev"] == "spindle" and e["spindle"] == "S1"]
homing_t = next(t for t, m in spindle if m == "homing")
position_t = next(t for t, m in spindle if m == "position")
drive_t = {m: [e["t"] for e in events if e["ev"] == "drive" and e["axis"] == "S1" and e["mode"] == m] for m in ("homing", "csp")}
check(drive_t["homing"] and 0 <= drive_t["homing"][0] - homing_t <= 0.005, "homing mode follows G74 within 5 cycles")
check(drive_t["csp"] and 0 <= drive_t["csp"][0] - position_t <= 0.005, "position mode follows M19 within 5 cycles")
check(not [e for e in events if e["ev"] == "error"], "spindle_modes.nc: no error")

rc, events, rows = run(program="home.nc")
check(rc == 0 and not [e for e in events if e["ev"] == "error"], f"home.nc: exit {rc}, no error")
drive = [(e["axis"], e["mode"]) for e in events if e["ev"] == "drive" and e["axis"] in "XYZ"]
check(drive[3:] == [("Z", "homing"), ("Z", "csp"), ("X", "homing"), ("Y", "homing"), ("X", "csp"), ("Y", "csp")],
      f"home.nc: Z's drive homes, then X's and Y's: {drive}")
waits = [e["ev"] for e in events if e["ev"] in ("wait", "wait_end") and e.get("reason") == "homing"]
check(waits == ["wait", "wait_end"] * 2, f"home.nc: the homing block waits for its drives: {waits}")
# Z stood at 10 when its drive homed (the simulated drive homes to 0): the
# trace's Z takes the drive's 0 in one cycle and stays there.
zcol = next(k for k in rows[0] if k.strip().upper().startswith("Z"))
zs = [float(r[zcol]) for r in rows]
jumps = [i for i, (a, b) in enumerate(zip(zs, zs[1:])) if abs(b - a) > 500 * 0.001 + 1e-9]
check(len(jumps) == 1 and abs(zs[jumps[0]] - 10) < 1e-9 and zs[jumps[0] + 1] == 0.0,
      f"home.nc: Z's reference taken once, from 10 to the drive's 0: {[(zs[i], zs[i + 1]) for i in jumps]}")
check(abs(zs[-1]) < 1e-9, f"home.nc: Z ends at pos_refpkt 0, got {zs[-1]}")

for f in failures:
    print("FAIL:", f)
print("ok" if not failures else f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
