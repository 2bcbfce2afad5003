; TF5200 manual: Counting loop ($FOR) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206929163.html
; own equivalent: a counting loop with start, end and increment, the counter
; used in an axis word with a function; a V. variable as counter; a
; negative increment
#VAR
V.L.STEP = 0
#ENDVAR
N10 G01 F5000
N100 $FOR P1 = 6, 30, 4         ; 6 10 14 ... 30
N110   X SIN [P1 * 3]           ; X = sin(3 * P1 degrees)
N120   Y[P1]
N130 $ENDFOR
N140 $FOR V.L.STEP = 3, 1, -1   ; 3 2 1
N150   Z[-V.L.STEP * 2]
N160 $ENDFOR
N170 M30
