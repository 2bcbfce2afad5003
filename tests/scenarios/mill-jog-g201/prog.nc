N10 G90 G0 X0 Y0 Z0
N20 G201 X1                  ; X in manual mode
N30 G1 Y50 F1500             ; 2 s: the operator jogs meanwhile
N40 G202
N50 M30
