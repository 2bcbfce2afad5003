#!/usr/bin/env python3
"""Issue 43's synthetic chord programs (bench/chord_program.py) on the
bench's machine at equal limits (a_beschl = a_brems = a_max), blended with
PATH_DEV 0.01, through `nck run` and bench/feed_ratio.py:
- D1: 200 chords of 1.0 mm with alternating 4 degree kinks at F6000 (the
  fillets must share each chord between its two corners, or every other
  corner is taken almost at a stop: 3.0 times the ideal before): <= 1.05;
- D1: 300 chords of 0.2 mm with 1 degree kinks at F1016, zigzag and arc
  (each fillet sized for the feed, long enough for the profile): <= 1.01;
Each is also run with a line holding only the F word before every move
(M1, CAM posts write them): the ratio must not change by more than 0.5 %.
- D2: the 0.2 mm chords unblended: their 1 degree kinks pass at the feed
  (a kink may take half of a_max in the cycles that keep the speed; before,
  at equal limits, every kink was a stop: 1.524 and 1.480): <= 1.01.
- item 3: 400 chords of 0.25 mm turning 0.5 degree one way at F3000 under
  TRAPEZ, smoothed into a spline and planned across (1.984 with fillets,
  whose curvature steps the jerk rule held to a crawl): <= 1.10.
usage: chord_ratio_test.py NCK SOURCE_DIR"""
import pathlib
import re
import subprocess
import sys
import tempfile

nck, source = sys.argv[1], pathlib.Path(sys.argv[2])
machine = source / "bench" / "machines" / "equal-limits"
cases = [  # (name, chord_program.py arguments, PATH_DEV or None (unblended), bar[, slope])
    ("1.0 mm 4 deg zigzag F6000", ["200", "1.0", "4", "6000"], "0.01", 1.05),
    ("0.2 mm 1 deg zigzag F1016", ["300", "0.2", "1", "1016"], "0.01", 1.01),
    ("0.2 mm 1 deg arc F1016", ["300", "0.2", "1", "1016", "--arc"], "0.01", 1.01),
    ("0.2 mm 1 deg zigzag F1016 unblended", ["300", "0.2", "1", "1016"], None, 1.01),
    ("0.2 mm 1 deg arc F1016 unblended", ["300", "0.2", "1", "1016", "--arc"], None, 1.01),
    ("0.25 mm 0.5 deg arc F3000 TRAPEZ", ["400", "0.25", "0.5", "3000", "--arc"], "0.01", 1.10, "TRAPEZ"),
]


def ratio(tmp, args, path_dev, f_lines, slope):
    program = pathlib.Path(tmp) / "chords.nc"
    extra = ["--f-lines"] if f_lines else []
    subprocess.run([sys.executable, source / "bench" / "chord_program.py", program, *args, *extra], check=True)
    blend = (["--path-dev", path_dev] if path_dev else []) + (["--slope", slope] if slope else [])
    out = subprocess.run([sys.executable, source / "bench" / "feed_ratio.py", nck, machine, program, *blend],
                         capture_output=True, text=True)
    m = re.match(r"ratio ([0-9.]+)", out.stdout)
    if out.returncode != 0 or not m:
        print(out.stdout + out.stderr)
        return None
    return float(m.group(1))


ok = True
with tempfile.TemporaryDirectory() as tmp:
    for name, args, path_dev, bar, *slope in cases:
        slope = slope[0] if slope else None
        plain, with_f = ratio(tmp, args, path_dev, False, slope), ratio(tmp, args, path_dev, True, slope)
        good = plain is not None and with_f is not None and plain <= bar and abs(with_f - plain) <= 0.005 * plain
        print(f"{name}: ratio {plain}, with F lines {with_f}, bar {bar}: {'ok' if good else 'FAILED'}")
        ok = ok and good
print("chord ratio: ok" if ok else "chord ratio: FAILED")
sys.exit(0 if ok else 1)
