; A circle whose end point is not on it: centre (10, 0), start radius 10,
; end radius 20. The channel stops with error 930004.
N10 G17 G90 G0 X0 Y0 Z0
N20 G2 X30 Y0 I10 J0 F600
N30 G0 X5
N40 M30
