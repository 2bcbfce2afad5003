; A longitudinal thread, pitch 2 mm, in three G33 passes: each pass starts
; when the spindle passes its zero mark, so all three cut the same groove.
; 400 rpm x 2 mm = 800 mm/min along Z. Positions in radius. Runs to M30.
%thread
N10 G18 G90
N20 M3 S400
N30 G0 X36 Z5
N40 G1 X34.6 F500         ; 1st depth
N50 G33 Z-30 K2           ; 1st pass
N60 G0 X36
N70 Z5
N80 G1 X34.2              ; 2nd depth
N90 G33 Z-30 K2           ; 2nd pass
N100 G0 X36
N110 Z5
N120 G1 X33.9             ; final depth
N130 G33 Z-30 K2          ; 3rd pass
N140 G0 X36
N150 Z5
N160 M5
N170 M30
