; TF5200 manual (TwinCAT CNC programming manual): Arithmetical expressions <expr> - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556614795.html
; own equivalent: point before dash, square brackets for grouping and for
; function arguments, P parameters in expressions and axis words
N10 P1 = 3 P2 = 4 P6 = 5
N20 P5 = [[SIN[P1*10.00] + P2] / P6]   ; (0.5 + 4) / 5 = 0.9
N30 P7 = SQRT[P1*P1 + P2*P2]           ; 5
N40 P8 = ABS[-2.5] + 2 * 3 - 1         ; 7.5
N50 P9 = ATAN2[1, 1] + INT[7.8] MOD 4  ; 45 + 3 = 48
N60 G01 X[P5 * 10] Y[P7 + P8] Z[-P9 / 8] F3000   ; X9 Y12.5 Z-6
N70 H70=[P9 * 100]                     ; 4800
N80 M30
