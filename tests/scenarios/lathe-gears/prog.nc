; Automatic gear stage of S1 (autom_range 1): stage 1 20-800 rpm, stage 2
; 600-2500, stage 3 2000-8000 (examples/lathe/channel1.lis).
N10 G18 G90 G0 X40 Z5
N20 S500 M3          ; stage 1 covers 500 rpm: no change
N30 S1500            ; only stage 2 covers it: M41
N40 G1 Z0 F3000
N50 M42 S3000        ; stage 3 by hand
N60 G1 Z-5
N70 M5
N80 M30
