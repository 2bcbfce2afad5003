; TF5200 manual: Spindle-specific homing (G74) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208221195.html
; own equivalent: homing the main spindle in spindle syntax (on this mill S2
; has no position feedback and cannot home), then in DIN syntax together
; with the linear axes
N10 S[G74]                      ; home S
N20 G74 X1 Y2 Z3                ; home the axes (order: X, Y, then Z)
N30 M30
