; TF5200 manual: Dwell time (G04), (#TIME) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206132747.html
; own equivalent: every form of the dwell - first main axis, direct value,
; P parameter, V.L. variable, spindle revolutions, and #TIME
#VAR
V.L.PAUSE = 0.4
#ENDVAR
N10 G04 X0.6                    ; 0.6 s by the first main axis
N20 G04 0.3                     ; 0.3 s directly
N30 P7 = 0.25
N40 G04 P7                      ; 0.25 s from a parameter
N60 G04 V.L.PAUSE               ; 0.4 s from a variable
N70 M3 S600
N80 G04 S4                      ; 4 revolutions (0.4 s at 600 rpm)
N90 #TIME 0.35                  ; 0.35 s
N100 #TIME P7                   ; 0.25 s
N110 #TIME V.L.PAUSE            ; 0.4 s
N120 M5
N130 M30
