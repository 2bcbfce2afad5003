; TF5200 manual: Programming in spindle-specific syntax - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208178187.html
; own equivalent: several spindle commands for S in one bracket (speed,
; positioning, user M and H functions) and S2 programmed independently in
; the same block
N10 S[M3 REV800 M19 POS90 M=10 H=25]  S2[M4 REV4000]
N20 S2[M5]
N30 M30
