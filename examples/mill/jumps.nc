; Mill example: $GOTO jumps. A forward jump over a block, a backward jump
; loop counted in a V.L. variable, and $IF ... $GOTO in one line with a
; P parameter. Runs to M30.
%jumps
#VAR
  V.L.PASS = 0           ; passes of the backward loop
#ENDVAR
N10 G17 G90 G71
N20 G0 X0 Y0 Z10
N30 $GOTO N50            ; forward: N40 never runs
N40 G0 X99
N50: G1 X10 F1000
; backward loop: three passes, 5 mm further in Y each
N60: V.L.PASS = V.L.PASS + 1
N70 G1 Y[5 * V.L.PASS]
N80 $IF V.L.PASS < 3 $GOTO N60
; string label and a parameter condition
N90 P1 = 2
N100 $IF P1 == 2 $GOTO [DONE]
N110 G0 Z99
N120 [DONE] G1 X20
N130 G0 Z10
N140 M30
