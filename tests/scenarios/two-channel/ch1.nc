; Channel 1 dwells 1 s, then moves.
N10 G4 X1
N20 G17 G90 G0 X10 Y20 Z5
N30 M30
