; TF5200 manual: Tapping (G331/ G332) - https://infosys.beckhoff.com/content/1033/tf5200_turning_functions/413715595.html
; own equivalent: rigid tapping with a position-controlled spindle; G331
; cuts with pitch K and speed S, G332 retracts with automatic reversal and
; takes pitch and speed from G331
N10 G90 G00 X25 Y25 Z4
N20 M05
N30 G331 Z-16 K1.5 S500         ; right-hand thread, pitch 1.5 mm
N40 G332 Z4                     ; retract
N50 G00 Z30
N60 M30
