; issue 46: a spindle on a conventional drive through HAL (hal_test.py
; vfd-spindle, examples/hal/mill-velocity.hal): S1's VFD is 5 % slow; it
; turns on its own speed loop, and M19 ends in position only because nck
; closes the position loop with kv.
N10 M3 S600
N20 G4 X0.5
N30 S.POS=90 M19 S400
N40 G4 X0.3
N50 M30
