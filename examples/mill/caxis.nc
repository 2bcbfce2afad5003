; Mill example: C-axis machining. The main spindle S1 becomes the rotary
; path axis C (#CAX; default_ax_name_of_spindle C, achs_mode 0x0204), moves
; with X, then mills a square pocket on the face of a part on the table
; (#FACE [X, C]: C is the Cartesian second axis in mm) and crosses the
; centre. Machine positions at the block ends (README, tests):
;   N50 X20 C180, N80 X14.1421 C315, N100..N130 C 405 495 585 675,
;   N150 X20 C540, N160 X-20 C540 (through the centre C stays).
%caxis
N10 G17 G90 G0 X0 Y0 Z50
N20 M5                      ; C-axis mode needs the spindle at standstill
N30 #CAX [S, C]             ; S1 is the path axis C from here (degrees)
N40 G0 C90                  ; C alone at rapid
N50 G1 X20 C180 F600        ; X and C together; F is X's feed, C follows
N60 #FACE [X, C]            ; face machining: C is Cartesian (mm) from here
N70 G0 Z2
N80 X10 C-10                ; start corner of the pocket (X14.1421 C315)
N90 G1 Z-1 F300
N100 X10 C10 F600           ; a 20 mm square around the centre
N110 X-10 C10
N120 X-10 C-10
N130 X10 C-10
N140 G0 Z2
N150 X-20 C0                ; (X20 C540)
N160 G1 X20 C0 F600         ; straight through the centre: X 20 -> -20, C stays
N170 G0 Z50
N180 #FACE OFF              ; back to machine X and C (degrees)
N190 #CAX OFF               ; S1 is a spindle again
N200 M30
