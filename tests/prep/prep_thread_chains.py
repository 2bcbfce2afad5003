#!/usr/bin/env python3
"""--prep-thread gives the plain run's outputs where the kernel plans chains
(issue 42's bar; issue 43): the first 2,000 lines of the surface-finishing
program (bench/surface_program.py) with PATH_DEV 0.01 under TRAPEZ (its
smoothed spans chain) and HSC. A chain once looked at every queued command,
and how many were queued depended on when preparation ran, so one block
event came 1 ms apart and the final states differed; it now looks no
further than kChainHorizon. Events and final state equal byte for byte.

  prep_thread_chains.py NCK SOURCE_DIR
"""
import pathlib
import subprocess
import sys
import tempfile

NCK, SRC = sys.argv[1], pathlib.Path(sys.argv[2])
failures = 0


def run(machine, program, out, *extra):
    events, final = out.with_suffix(".jsonl"), out.with_suffix(".json")
    subprocess.run([NCK, "run", str(machine), str(program), "--events", str(events), "--final", str(final),
                    "--no-progress", *extra], capture_output=True, timeout=300, check=True)
    return events.read_bytes(), final.read_bytes()


with tempfile.TemporaryDirectory() as d:
    d = pathlib.Path(d)
    subprocess.run([sys.executable, str(SRC / "bench/surface_program.py"), str(d / "surface.nc")], check=True,
                   capture_output=True)
    rows = (d / "surface.nc").read_text().splitlines()[:2000]
    for slope in ("TRAPEZ", "HSC"):
        program = d / f"{slope}.nc"
        program.write_text("\n".join([f"#SLOPE [TYPE={slope}]", "#CONTOUR MODE [DEV PATH_DEV=0.01]", "G261", *rows,
                                      "M30"]) + "\n")
        plain = run(SRC / "examples/mill", program, d / f"{slope}-plain")
        threaded = run(SRC / "examples/mill", program, d / f"{slope}-thread", "--prep-thread")
        same = plain == threaded
        print(("ok   " if same else "FAIL ") + f"{slope}: --prep-thread equals the plain run (events, final state)")
        failures += 0 if same else 1
sys.exit(1 if failures else 0)
