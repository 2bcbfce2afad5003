; TF5200 manual: Example: Configuring and programming a PLC spindle - https://infosys.beckhoff.com/content/1033/tf5200_spindle/287391627.html
; own equivalent (on the mill's NC spindle, programmed the same way): DIN
; syntax with M03/M04/M05 and M19 S.. S.POS.., then the same sequence in
; spindle-specific syntax
N10 M03 S1500
N20 G01 Z-5 F2000
N30 M04 S1500
N40 Z10
N50 M05
N60 M19 S250 S.POS120
N110 S[M03 REV1500]
N120 Z-5
N130 S[M04 REV1500]
N140 Z10
N150 S[M05]
N160 S[M19 REV250 POS210]
M30
