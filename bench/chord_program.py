#!/usr/bin/env python3
"""Write a chord program: N G1 chords of LENGTH mm in the XY plane, each
turned KINK degrees from the one before, at FEED (issue 43's synthetic
programs for fine segments). Turns alternate left and right (zigzag) or
all go one way (arc); --f-lines puts a line with only the F word before
every move, as CAM post-processors write it.
usage: chord_program.py OUT.nc N LENGTH_MM KINK_DEG FEED [--arc] [--f-lines]"""
import math
import sys

out, n, length, kink, feed = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
arc, f_lines = "--arc" in sys.argv[6:], "--f-lines" in sys.argv[6:]
lines = ["G90 G17 G54", "G0 X0 Y0 Z0", f"F{feed:g}"]
x = y = heading = 0.0
for i in range(n):
    heading += kink if arc or i % 2 == 0 else -kink
    x += length * math.cos(math.radians(heading))
    y += length * math.sin(math.radians(heading))
    if f_lines:
        lines.append(f"F{feed:g}")
    lines.append(f"G1 X{x:.4f} Y{y:.4f} F{feed:g}")
lines += ["G0 Z5", "M2"]
open(out, "w").write("\n".join(lines) + "\n")
