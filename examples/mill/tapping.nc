; Tapping without a compensating chuck (G63), the second example of FCT-S1
; 2.8.6 as written: the spindle is positioned (M19), then follows Z as a
; tracking axis with F = S x pitch (300 mm/min = 200 rpm x 1.5 mm); the
; negative S retracts with the spindle turning back. G01 ends G63.
%Tapping_G63

N05 X0 Y0 Z0
N10 G91 Z100
N20 M19 S.POS180 M3 S100    ; position spindle

N30 G63 Z-50 F300 S200     ; tap
N40 Z100 S-200             ; retract from threaded bore

N50 G01 X200 F3000         ; reposition, deselect tapping

N60 G63 Z-70 F300 S200     ; tap
N70 Z100 S-200             ; retract from threaded bore

N80 M05 G01 X300 F1000
N90 M30
