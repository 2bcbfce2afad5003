; TF5200 manual: Switch branching ($SWITCH) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206908427.html
; own equivalent: the switch value computed and assigned to P1 in the
; $SWITCH block, a $CASE with an expression, $BREAK, $DEFAULT
N10 P1 = 3 P2 = 4 P3 = 2
N100 $SWITCH P1=INT [P1*P2/P3]  ; P1 = 6
N110 $CASE 1
N120   G01 X10 F3000
N130 $BREAK
N150 $CASE P2 + 2               ; 6: this branch runs
N160   G01 X60 F3000
N170 $BREAK
N300 $CASE -5
N320   G01 X-50 F3000
N330 $BREAK
N350 $DEFAULT
N360   G01 X99 F3000
N390 $ENDSWITCH
N400 H40=P1                     ; 6
N410 $SWITCH P2 / 3             ; 1.3333: no case within 0.001
N420 $CASE 1.33
N430   G01 Y13 F3000
N440 $BREAK
N450 $CASE 4 / 3                ; equal: this one
N460   G01 Y40 F3000
N470 $BREAK
N480 $ENDSWITCH
N500 M30
