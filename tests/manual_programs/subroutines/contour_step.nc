; global subroutine for global_subroutine.nc: one step of 12 mm in X
; (no local subroutines here, so no %name is needed)
N10 G91 G01 X12 F2400
N20 G90
N30 M17
