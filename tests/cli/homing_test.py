#!/usr/bin/env python3
"""nck run and homing (P-AXIS-00277; docs/cli.md "nck run --unhomed").

  homing_test.py NCK SOURCE_DIR

tests/data/machine_homing: X and Z require homing, Y not. The dry run
assumes a homed machine (move.nc runs as on any machine); with --unhomed
the block that moves X is refused (930740 naming X at its line) before
anything moved; G74 first homes, then the program runs; --final lists
`homed` per axis only where the machine data require homing.
Exit 1 on any failed check.
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

NCK, SRC = sys.argv[1], Path(sys.argv[2])
MACHINE = SRC / "tests/data/machine_homing"
failures = 0


def check(name, cond, detail=""):
    global failures
    print(("ok   " if cond else "FAIL ") + name + ("" if cond else f": {detail}"))
    failures += 0 if cond else 1


def run(machine, program, *extra):
    with tempfile.TemporaryDirectory() as d:
        events, final = Path(d) / "e.jsonl", Path(d) / "f.json"
        p = subprocess.run([NCK, "run", str(machine), str(program), "--events", str(events), "--final", str(final),
                            "--no-progress", *extra], capture_output=True, text=True, timeout=60)
        lines = [json.loads(x) for x in events.read_text().splitlines() if x]
        return p, [e for e in lines if e["ev"] == "error"], json.loads(final.read_text())


p, errors, final = run(MACHINE, MACHINE / "move.nc")
x = final["channels"][0]["axes"]["X"]
check("without --unhomed the run is as before (homed, X at 40)",
      p.returncode == 0 and not errors and x["homed"] is True and x["mcs"] == 40, p.stderr)

p, errors, final = run(MACHINE, MACHINE / "move.nc", "--unhomed")
axes = final["channels"][0]["axes"]
e = errors[0] if errors else {}
check("--unhomed: the move of X is refused with 930740 naming X at line 2, nothing moved",
      p.returncode != 0 and len(errors) == 1 and e.get("id") == 930740 and e.get("line") == 2 and
      "axis X is not homed" in e.get("msg", "") and axes["X"]["homed"] is False and axes["X"]["mcs"] == 0 and
      axes["Y"]["mcs"] == 0 and "930740" in p.stderr, f"{errors} {axes} {p.stderr}")

p, errors, final = run(MACHINE, MACHINE / "home_then_move.nc", "--unhomed")
axes = final["channels"][0]["axes"]
check("--unhomed: Y moves unhomed, G74 homes X and Z, then the program runs to its end",
      p.returncode == 0 and not errors and axes["X"]["homed"] and axes["Z"]["homed"] and
      axes["Y"]["homed"] is False and axes["Y"]["mcs"] == 10 and axes["X"]["mcs"] == 40, f"{errors} {axes} {p.stderr}")

mill = SRC / "examples/mill"
with tempfile.TemporaryDirectory() as d:
    prog = Path(d) / "p.nc"
    prog.write_text("G0 X10 Y5\nM30\n")
    p, errors, final = run(mill, prog, "--unhomed")
check("a machine without P-AXIS-00277 moves unhomed and its final state has no `homed`",
      p.returncode == 0 and not errors and "homed" not in final["channels"][0]["axes"]["X"], f"{errors} {p.stderr}")

sys.exit(1 if failures else 0)
