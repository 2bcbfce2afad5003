; TF5200 manual: Linear interpolation (G01) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206082059.html
; own equivalent: G01 at a programmed feed, absolute then incremental; the
; third main axis Z moves with X and Y on the same straight line
N05 G00 G90 X30 Y10 Z-5
; absolute dimensions
N10 G01 G90 X70 Y45 Z-20 F1800  ; P1 -> P2 at 1800 mm/min
N20 X110 Y90 Z-35               ; P2 -> P3, same feed (modal)
; incremental dimensions
N30 G01 G91 X15 Y-30 Z5 F1200
N40 X-25 Y10 Z10
N50 G90
N99 M30
