; Mill example: a slot around a cylinder of radius 60 mm clamped on the
; rotary axis (#CYL [Z, C, X60]: C is the developed length in mm on the
; reference radius). 100 mm of C = 100/60 rad = 95.4930 deg of the spindle.
; Machine positions at the block ends (README, tests):
;   N70 Z10 C0, N80 C95.4930, N90 Z40 C143.2394, N100 Z10 C47.7465.
%cylinder
N10 G17 G90 G0 X80 Y0 Z10
N20 M5
N30 #CAX [S, C]
N40 G0 C0
N50 #CYL [Z, C, X60]        ; the lateral surface: Z and developed C in mm
N60 G0 X62
N70 G1 X58 F300             ; 2 mm deep into the surface
N80 G1 C100 F600            ; the slot runs 100 mm round the cylinder
N90 Z40 C150                ; then diagonally (helix on the cylinder)
N100 Z10 C50
N110 G0 X80
N120 #CYL OFF
N130 #CAX OFF
N140 M30
