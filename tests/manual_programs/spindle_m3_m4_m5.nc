; TF5200 manual: Spindle-specific movement (M3, M4, M5) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208191499.html
; own equivalent: the main spindle S and the second spindle S2 in spindle
; syntax - a speed stored while stopped, direction changes, a new speed
; while turning, a speed stored with M05
N10 S[REV700]                   ; stored, no rotation (M05 at start)
N20 S[M03]                      ; cw at 700 rpm
N30 S[M04]                      ; ccw at 700 rpm
N40 S[REV450]                   ; ccw at 450 rpm
N50 S[M05 REV350]               ; stop, 350 rpm stored
N60 S[M04]                      ; ccw at 350 rpm
N70 S[M05]                      ; stop
N80 S[M03 REV1100] S2[M04 REV2400]   ; both spindles in one block
N90 S[M05] S2[REV1600]          ; S stops, S2 on at 1600 rpm
N100 S[M04]                     ; S ccw at 1100 rpm
N110 M30
