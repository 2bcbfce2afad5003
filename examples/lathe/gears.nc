; Lathe example: automatic gear-stage selection of the main spindle S1
; (autom_range 1; stages 20-800, 600-2500, 2000-8000 rpm in channel1.lis).
; A speed outside the current stage makes the spindle approach the stage's
; change position, the PLC shifts (gear_change_time_ms), and the new stage's
; getriebe[i] data applies. Runs to M30.
%gears
N10 G18 G90 G0 X40 Z5
N20 S500 M3                ; stage 1 covers 500 rpm
N30 G1 Z-20 F200
N40 S700                   ; stage 1 still covers it: no change
N50 S1500                  ; only stage 2 covers it: gear change M41
N60 G1 X30 F150
N70 M42 S3000              ; manual selection of stage 3
N80 G1 Z-40
N90 M5
N100 G0 X40 Z5
N110 M30
