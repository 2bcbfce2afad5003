; Jerk-limited motion (#SLOPE, issue 30): the same square and circle run
; three times, with STEP (P-CHAN-00071's default: acceleration steps),
; TRAPEZ (trapezoidal acceleration, jerk <= a/tr) and SIN2 (sin^2 ramps,
; jerk <= (pi/2) a/tr). The mill's ramp times are the TF5200 defaults
; (50 ms for a_beschl/a_brems, 10 ms for G0). Compare the three passes in
; the trace (--trace-columns path.a,path.j shows the path's acceleration
; and jerk); runs to M30.
%L SQUARE
N1000 G1 X60 F6000
N1010 Y30
N1020 G2 X60 Y-10 I0 J-20 F3000
N1030 G1 X0 Y-10 F6000
N1040 Y0
M17

%slope
N10 G17 G90 G71
N20 G0 X0 Y0 Z2
N30 #SLOPE [TYPE=STEP]
N40 LL SQUARE
N50 #SLOPE [TYPE=TRAPEZ]
N60 LL SQUARE
N70 #SLOPE [TYPE=SIN2]
N80 LL SQUARE
N90 #SLOPE DEFAULT     ; back to P-CHAN-00071 (STEP on this mill)
N100 G0 X0 Y0 Z10
N110 M30

