; TF5200 manual (TwinCAT CNC programming manual): The $CONTINUE-statement - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556891275.html
; own equivalent: $CONTINUE skips the rest of a loop pass, $BREAK leaves the
; loop
N05 G01 F4000 P20 = 0
N10 $FOR P1 = 1, 8, 1
N20   $IF P1 MOD 2 == 0         ; even passes: skip the move
N30     $CONTINUE
N40   $ENDIF
N50   $IF P1 > 5
N60     $BREAK                  ; leave at P1 = 7
N70   $ENDIF
N80   X[P1 * 5]                 ; X5 X15 X25
N85   P20 = P20 + 1
N90 $ENDFOR
N100 H50=P20                    ; 3 moves
N110 M30
