; Clamp group 1 (--clamp-index 1: X10 Y-5) under G55 (X200 Y100 Z-150).
N10 G17 G90 G55 G0 X0 Y0 Z0
N20 M30
