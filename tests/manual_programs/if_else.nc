; TF5200 manual: The IF - ELSE branch - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206901003.html
; own equivalent: the four forms - $IF on a decimal value (TRUE from
; |value| >= 0.5), a comparison, $ELSE, and $ELSEIF; H20..H23 report which
; branch ran
N05 P1 = 0.4 P2 = 2.5 P3 = 0
N10 $IF P1                      ; |0.4| < 0.5: FALSE
N20   H20=1
N30 $ELSE
N40   H20=2
N50 $ENDIF
N60 P1 = -0.75
N70 $IF P1                      ; |-0.75| >= 0.5: TRUE
N80   H21=1
N90 $ENDIF
N100 $IF P2 >= 0.5              ; comparison
N110   H22=1
N120 $ENDIF
N130 $IF P3 == 1
N140   G01 X10 F2000
N150 $ELSEIF P2 > 2
N160   G01 X20 F2000
N170   H23=2
N180 $ELSE
N190   G01 X30 F2000
N200 $ENDIF
N210 M30
