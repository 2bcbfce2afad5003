; issue 46: the PLC's spindle controls as HAL pins (hal_test.py
; spindle-controls): nck.spindle.S1.override scales S1's speed,
; nck.spindle.S1.feedhold holds it.
N10 M3 S1000
N20 G4 X3
N30 M30
