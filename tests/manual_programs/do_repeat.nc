; TF5200 manual: Verification of running condition at loop end ($DO), ($REPEAT) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206946827.html
; own equivalent: both loops that test at their end - $DO ... $ENDDO runs
; while its condition is TRUE, $REPEAT ... $UNTIL until its condition is
; TRUE; each runs at least once
N10 G01 X0 Y0 Z0 F6000
N20 P2=6 P1=0
N30 $DO
N40   P1=P1+1.5
N50   XP1
N60 $ENDDO P1 <= P2             ; 1.5 3 4.5 6 7.5 -> X7.5
N70 P5=0
N80 $REPEAT
N90   P5=P5+2
N100  YP5
N110 $UNTIL P5 > 7              ; 2 4 6 8 -> Y8
N120 $DO                        ; runs once although FALSE at once
N130   Z-3
N140 $ENDDO 0
N150 M30
