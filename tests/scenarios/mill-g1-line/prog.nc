; One straight feed move from machine zero.
N10 G17 G90 G0 X0 Y0 Z0
N20 G1 X100 Y50 F6000
N30 M30
