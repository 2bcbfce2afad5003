; Facing with constant cutting speed (G96): the spindle speed follows the
; X position every cycle, n = 1000 v / (2 pi X), up to the G196 limit.
; G97 keeps the speed reached. Positions in radius. Runs to M30.
%facing
N10 G18 G90
N20 G196 S2000            ; G96 never turns faster than 2000 rpm
N30 M3 S1000              ; endless rotation, gear stage 2 (range_table)
N40 G0 X40 Z2
N50 G96 S150              ; 150 m/min: 596.8 rpm at X40
N60 G1 Z0 F300
N70 G1 X0 F150            ; face to the centre: 1193.7 rpm at X20, 2000 from X11.94
N80 G0 Z2
N90 G97                   ; freeze the last speed
N100 G0 X40
N110 M5
N120 M30
