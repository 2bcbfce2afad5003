; G63 tapping with a programmed speed both gear stages could not reach
; together with the feed: the spindle follows Z in the gear stage of
; def_cax_gear_st (2: 100 rpm), not in the stage it turned in (1: 200 rpm).
N10 G18 G90 G0 X0 Z5
N20 M5                      ; G63 needs the spindle at standstill
N30 S150 G63 Z-5 F187.5     ; pitch F / S = 1.25 mm/rev
N40 G1 Z10 F1000
N50 M30
