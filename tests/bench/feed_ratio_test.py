#!/usr/bin/env python3
"""bench/feed_ratio.py on a program whose ideal is worked out by hand: a
60 mm line and a half circle of radius 10 mm (31.416 mm) at F3000, after a
plunge at F300 that is not part of the feed section: ideal
(60 + 10 pi) / 50 mm/s = 1.828 s. The measured time lies above it (the
path starts from standstill) and below 1.5 times it, on examples/mill and
on the bench's machine at equal limits.
usage: feed_ratio_test.py NCK SOURCE_DIR"""
import pathlib
import re
import subprocess
import sys
import tempfile

nck, source = sys.argv[1], pathlib.Path(sys.argv[2])
program = "G90 G17 G54\nG0 X0 Y0 Z1\nG1 Z0 F300\nG1 X60 F3000\nG2 X60 Y20 I0 J10\nG0 Z5\nM2\n"
ok = True
# examples/mill and the bench's machine at equal limits (bench/machines/equal-limits)
for machine in (source / "examples" / "mill", source / "bench" / "machines" / "equal-limits"):
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "ratio.nc"
        path.write_text(program)
        out = subprocess.run([sys.executable, source / "bench" / "feed_ratio.py", nck, machine, path],
                             capture_output=True, text=True)
    print(machine.name, out.stdout + out.stderr)
    m = re.match(r"ratio ([0-9.]+)  time ([0-9.]+) s  ideal ([0-9.]+) s  feed blocks 2", out.stdout)
    ok = ok and out.returncode == 0 and m is not None and m.group(3) == "1.828" and 1.0 < float(m.group(1)) < 1.5
print("feed ratio: ok" if ok else "feed ratio: FAILED")
sys.exit(0 if ok else 1)
