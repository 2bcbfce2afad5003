; CiA 402 example: the program waits until the drives of X, Y and Z are in
; operation enabled (a wait event, reason drive_enable), then mills a
; square. With fault.plc the drive of Y faults in the middle: error 940501
; names the axis, X and Z brake within their limits.
%enable
N10 G17 G90 G71
N20 G0 X0 Y0 Z5
N30 G1 Z-1 F600
N40 G1 X40 F1200
N50 G1 Y40
N60 G1 X0
N70 G1 Y0
N80 G0 Z5
N90 M30
