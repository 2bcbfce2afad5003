; TF5200 manual: Local, valid throughout subroutine (V.L.) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/207981323.html
; own equivalent: V.L. variables declared with and without data type and
; initial value, assigned, and used as axis values
#VAR
  V.L.DEPTH                       ; REAL64, 0.0
  V.L.COUNT : UNS32 = 150         ; UNS32, 150
  V.L.WIDTH : REAL64 = 12.5       ; REAL64, 12.5
  V.L.DONE : BOOLEAN              ; BOOLEAN, FALSE
  V.L.LENGTH = 40                 ; REAL64, 40.0
#ENDVAR
N10 V.L.DEPTH = -8
N20 G01 XV.L.LENGTH YV.L.WIDTH ZV.L.DEPTH F3000
N30 V.L.DONE = TRUE
N40 $IF V.L.DONE
N50   H60=V.L.COUNT
N60 $ENDIF
N70 M30
