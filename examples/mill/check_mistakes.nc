; nck check's example: six mistakes, each in a block of its own.
;   nck check examples/mill examples/mill/check_mistakes.nc
; lists all six with their values; `nck run` stops at the first (line 6).
N10 G17 G90 G71
N20 G0 X0 Y0 Z10
N30 G1 X10                ; a feed move before any F (930002)
N40 G1 X20 F600
N50 G2 X40 Y0 I5 J0       ; start radius 5, end radius 15: not one circle (930004)
N60 G444 X30              ; no such G code (920005)
N70 G1 Y[P7]              ; P7 has no value yet (920022)
N80 G0 X650               ; X is 150 mm beyond its software limit of 500 mm (930003)
N90 G0 Z20
N100 L missing_sub.nc     ; the subroutine does not exist (920044)
N110 G0 X0 Y0
M30
