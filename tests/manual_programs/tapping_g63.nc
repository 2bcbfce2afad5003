; TF5200 manual: Tapping (G63) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208104203.html
; own equivalent: tapping an M8 thread (pitch 1.25 mm: F = S x pitch) with
; the spindle at standstill before G63; a negative S retracts; G04 does not
; end G63, G01 does
N10 G90 G00 X40 Y30 Z5 D3
N20 M05
N30 G63 Z-18 F500 S400          ; 400 rpm x 1.25 mm = 500 mm/min
N40 G04 0.2
N50 G63 Z5 S-400                ; retract, spindle reversed
N60 G01 Z20 F2000               ; ends G63
N70 M30
