; TF5200 manual (TwinCAT CNC programming manual): Radius programming (R) - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556764811.html
; own equivalent: circles by radius; R is modal (need not be repeated), a
; block with G02 and R alone does not move, a negative R gives the larger arc
N10 G90 G01 X0 Y0 F2400
N20 G02 X60 R30                 ; half circle, radius 30
N30 G03 X120 R30                ; and back the other way
N40 G02 R=15                    ; radius only: no motion in this block
N50 X150                        ; half circle with the modal R15
N60 G03 X180                    ; R15 still in force
N70 G02 X200 Y20 R-20           ; negative R: the 270 degree arc
N80 M30
