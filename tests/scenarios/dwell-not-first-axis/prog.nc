; G4 with further axes beside the first main axis warns (20685, the dwell is
; X's); G4 with another axis only is TF5200's error 20014.
N10 G4 X0.1 Z3
N20 G0 Y5
N30 G4 Z2
N40 M30
