; Two-channel example, channel 2: runs beside channel 1.
%channel2
N10 G90 G0 X0 Z5
N20 G1 X-15 Z-10 F1500
N30 G1 X-30 F800
N40 G0 X0 Z5
N50 M30
