; TF5200 manual (TwinCAT CNC programming manual): Coordinate preset (G92) - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556648587.html
; own equivalent: G92 shifts the program coordinates by the programmed values
; (absolute under G90); under G91 it takes effect at the next absolute word
N10 G90 G00 X0 Y0 Z0
N20 G92 X15 Z-20                ; preset offset X15 Z-20
N30 G01 X10 Z5 F2500            ; machine X25 Z-15
N40 G92 X0 Z0                   ; preset back to 0
N50 X10 Z5                      ; machine X10 Z5
N60 G92 X5 Y8
N70 G00 X0 G91                  ; relative 0: no motion in X
N80 G90 X0 Y0                   ; absolute: now the preset acts, machine X5 Y8
N90 M30
