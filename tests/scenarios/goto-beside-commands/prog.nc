; $GOTO with other commands in its block (TF5200: they may stand before and
; after it; the jump is the block's last action), and labels that carry
; commands themselves.
N10 G90 G0 X10 $GOTO [SECOND]   ; X10 first, then the jump
N20 G0 X99                      ; jumped over
N30 [SECOND] G0 Y20             ; a label with commands
N40 $GOTO [THIRD] G0 Z5         ; commands after the target: Z5, then the jump
N50 G0 Y99                      ; jumped over
N60 [THIRD] G91 X1 $GOTO N80 (a comment with $GOTO [NOWHERE])
N70 G0 Z99                      ; jumped over
N80: G90
[FINISH] M30
