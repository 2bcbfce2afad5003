; Twin-spindle machine (FCT-S1 2.8.3, Fig. 14): every form of synchronous
; operation on one program. The slave system (Y2, Z2, C2, S2) follows the
; master system (Y1, Z1, C1, S1); X is shared.
%twin
N10 G90 G0 X0 Y1=0 Z1=0 Y2=20 Z2=5 C1=0 C2=0
N20 #ENABLE AX LINK                  ; group 0 of the channel list: Y2=Y1, S2=S1
N30 S800 M3                          ; S1 and S2 turn at 800 rpm
N40 G1 Y1=50 F3000                   ; Y2 moves with Y1, from 20 to 70
N50 S.POS=90 M19 S300                ; S1 and S2 to 90 deg, each with its dynamics
N60 #DISABLE AX LINK                 ; the group enabled last: 0
N70 #SET AX LINK[2, [Z2=Z1, G, 0.01, 0.25]] ; gantry: Z2 keeps its 5 mm to Z1
N80 #ENABLE AX LINK[2]
N90 G1 Z1=-10 F1000                  ; Z2 from 5 to -5
N100 #AX LINK OFF[2]
N110 #AX LINK NBR[3, 17=6]           ; S3 slave of S1 by logical axis numbers
N120 #AX LINK ON[3]
N130 S1200 M4                        ; S1 and S3 turn counter-clockwise
N140 M5
N150 #AX LINK OFF ALL
N160 #SET AX LINK[4, [C2=C1, -1, 1]] ; mirrored: C2 turns against C1
N170 #ENABLE AX LINK[4]
N180 G1 C1=90 F5000                  ; C2 to -90 deg
N190 #DISABLE AX LINK[4]
N200 M30
