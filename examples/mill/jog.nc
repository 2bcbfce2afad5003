; Mill example: manual mode (jog.plc). The program holds at M0 and the
; operator jogs X and Y; a cycle start lets it go on. The jog stays in the
; machine position as a manual offset, as G201 handwheel travel does
; (docs/decisions.md, "Measuring, manual mode, jog and handwheel"), so the
; rest of the program runs shifted by it and #GET MANUAL OFFSETS reads it.
%jog
N10 G17 G90 G0 X0 Y0 Z0
N20 G1 X50 Y10 F3000
N30 M0                       ; the operator jogs now (jog.plc)
N40 G1 X60
N50 #GET MANUAL OFFSETS
N60 P1 = V.A.MANUAL_OFFSETS.X
N70 M30
