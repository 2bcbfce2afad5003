; G4 with the first main axis on a lathe in G18: X, the channel's first axis.
N10 G18 G90
N20 G4 X0.5
N30 G0 X10
N40 M30
