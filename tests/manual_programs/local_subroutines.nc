; TF5200 manual: Local subroutines (Call LL <string>) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206828043.html
; own equivalent: two local subroutines before the main program, one ended
; by M17, one by M29, called with LL from the main program after %name
%L POCKET_A
N1 G91 G01 X10 F3000
N2 Y10
N3 G90
N9 M17
%L POCKET_B
N11 G91 G01 X-5 F3000
N12 Y-5
N13 G90
N19 M29
%MILL_PART
N100 G90 G00 X0 Y0
N200 LL POCKET_A                ; X10 Y10
N210 LL POCKET_A                ; X20 Y20
N250 LL POCKET_B                ; X15 Y15
N300 M30
