; A dwell first: nothing moves for 1.5 s.
N10 G4 X1.5
N20 G0 X10
N30 M30
