; G54, tool length D1 and an additive G92 shift on X.
N10 G17 G90 G54 D1 G0 X0 Y0 Z50
N20 G92 X10
N30 G1 X0 F2000
N40 M30
