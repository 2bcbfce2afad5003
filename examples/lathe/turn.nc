; Lathe example: a facing pass and a profile with a radius, in G18 (Z/X
; plane). Positions in radius (no G51 yet). Runs to M30.
%turn
N10 G18 G90
N20 G0 X30 Z2
N30 G1 Z0 F300
N40 G1 X0 F150          ; face
N50 G0 Z2
N60 G0 X10
N70 G1 Z-20 F250
N80 G2 X20 Z-30 R10     ; radius 10 shoulder
N90 G1 Z-45
N100 G1 X25
N110 G0 X30 Z2
N120 M30
