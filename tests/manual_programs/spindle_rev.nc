; TF5200 manual: Spindle speed (REV) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208207115.html
; own equivalent: REV with M03/M04 sets and outputs the speed, with M05 it
; is only stored; REV alone changes the speed of a turning spindle
N10 S[REV250]                   ; stored
N20 S[M04]                      ; ccw 250 rpm
N30 S[M03 REV900]               ; cw 900 rpm
N40 S[REV600]                   ; M03 in force: cw 600 rpm
N50 S[M05 REV150]               ; stop, 150 rpm stored
N60 S[M04]                      ; ccw 150 rpm
N80 M30
