; TF5200 manual (TwinCAT CNC programming manual): Global sub-routines (Call L <string>) - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556851339.html
; own equivalent: a local subroutine called with LL and a global one called
; with L and its file name (path relative to this file)
%L LIFT
N11 G01 Z5 F2000
N19 M17
%333
N100 G00 X0 Y0 Z0
N110 LL LIFT
N200 L subroutines/contour_step.nc
N210 L subroutines/contour_step.nc   ; X24
N300 M30
