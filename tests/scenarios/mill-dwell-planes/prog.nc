; G4 X.. is the dwell in every plane on the mill (X: the channel's first axis).
N10 G18
N20 G4 X0.2
N30 G19
N40 G4 X0.3
N50 G17
N60 G4 X0.1
N70 G0 Y5
N80 M30
