; TF5200 manual: Dimension systems (absolute dimension/incremental dimension) (G90/G91) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206284043.html
; own equivalent: G90 targets refer to the origin, G91 values to the end of
; the previous motion block
N10 G90 G01 X40 Y20 F3000       ; absolute: to X40 Y20
N20 G91 X10 Y10                 ; incremental: +10 +10 -> X50 Y30
N30 X10                         ; X60
N40 G90 Y5                      ; absolute again: Y5
N50 M30
