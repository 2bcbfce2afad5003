; TF5200 manual: The $GOTO statement - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206915851.html
; own equivalent: expression labels (N..:) and string labels ([..]), jumps
; forward and backward, $IF with $GOTO in one line, commands before the
; jump in its block
N01 G01 X0 Y0 Z0 F3000
N05 P1 = 0
N10 G01 X15
N20 $GOTO N40                   ; forward over N30
N30 G01 Z-40
N40: G01 X30
N50 [AGAIN] P1 = P1 + 1
N60 G01 Y[P1 * 10]
N70 $IF P1 < 3 $GOTO [AGAIN]    ; backward, twice
N80 G01 X45 $GOTO [DONE]        ; X45 runs, then the jump
N90 G01 X-45
N100 [DONE] M30
