; TF5200 manual: Rapid traverse (G00) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206075403.html
; own equivalent: rapid positioning to a start point, then one absolute and
; one incremental G00 move (the manual's U axis is Z on this mill)
N05 G00 G90 X25 Y15 Z-10        ; start point P1
; absolute dimensions: P1 -> P2
N10 G00 G90 X140 Y95 Z-60
; incremental dimensions: back by a relative vector
N20 G00 G91 X-40 Y-35 Z25
N30 G90
N99 M30
