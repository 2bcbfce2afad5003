; A profile with feed per revolution (G95): the path speed is the spindle's
; speed times F in mm/rev, 800 rpm x 0.2 mm = 160 mm/min. Runs to M30.
%profile
N10 G18 G90
N20 M3 S800
N30 G0 X10 Z2
N40 G95 F0.2              ; 0.2 mm per revolution
N50 G1 Z-20
N60 G2 X20 Z-30 R10       ; radius 10 shoulder
N70 G1 Z-45
N80 G1 X25
N90 G94 G0 X30 Z2         ; back to mm/min
N100 M5
N110 M30
