; Mill example: manual mode with the handwheel. G201 lets the handwheel
; (manual.plc: +1.5 mm on X at 0.5 s) move X on top of the program; after
; G202 the offset stays, and #GET MANUAL OFFSETS gives it to the program.
%manual
N10 G17 G90 G0 X0 Y0 Z0
N20 G201 X1                  ; X in manual mode
N30 G4 X2                    ; the operator turns the handwheel meanwhile
N40 G202                     ; manual mode off; the offset stays in force
N50 #GET MANUAL OFFSETS
N60 P1 = V.A.MANUAL_OFFSETS.X
N70 G1 X[P1 * 2] F1000       ; X3 in the program: machine X 4.5
N80 M30
