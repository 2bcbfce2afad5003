; Two-channel example, channel 1: a square, then a dwell.
%channel1
N10 G17 G90 G0 X0 Y0 Z5
N20 G1 Z0 F500
N30 G1 X20 F2000
N40 Y20
N50 X0
N60 Y0
N70 #TIME 0.5
N80 G0 Z5
N90 M30
