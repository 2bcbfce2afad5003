; TF5200 manual: NC block numbers (N) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206817035.html
; own equivalent: block numbers from expressions - the loop counter in
; N[..] - and from a parameter (N P.., rounded to an integer); numbers need
; not ascend
N10 G01 X150 F3000
N20 $FOR P4 = 2, 8, 2
N[P4 * 50] X[P4 * 5]            ; N100 N200 N300 N400
N30 $ENDFOR
P9 = 12.6
NP9 Y15                         ; N13
N5 M30
