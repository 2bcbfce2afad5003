; Rigid tapping on the turning centre (G331/G332): the spindle is
; positioned to 0 deg, then follows Z as a tracking axis, 1.25 mm per turn
; at 500 rpm (625 mm/min); G332 retracts with the spindle turning back.
; Runs to M30.
%tapping
N10 G18 G90
N20 G0 X0 Z5
N30 G331 Z-20 K1.25 S500  ; tap 25 mm: 20 turns
N40 G332 Z5               ; retract: 20 turns back
N50 G0 Z10
N60 M30
