; Mill example: the main spindle S1 in DIN syntax and S2 in spindle syntax.
; S1's M3 is output to the PLC and the motion waits for its acknowledgement
; and for speed reached (m3_synch PLC_INFO MVS_SVS); S2 (MVS_SVS) waits for
; speed reached only. With spindle.plc: S1 at 50 % override from 1 s on;
; G167 runs at the programmed speed; the next speed is overridden again.
%spindle
N10 G17 G90 G0 X0 Y0 Z10
N20 S2000 M3                     ; S1 to 2000 rpm; the next motion waits
N30 G1 X50 F3000
N40 S2[M4 REV6000]               ; S2 counter-clockwise, 6000 rpm
N50 G1 Y30
N60 G4 X1                        ; dwell: the override of spindle.plc acts
N70 G167 S1000                   ; 1000 rpm whatever the override
N80 G4 X1
N90 S3000                        ; override acts again: 1500 rpm at 50 %
N100 G1 X0 Y0
N110 S2[M5]                      ; S2 stops
N120 S.POS=90 M19 S400           ; S1 positions to 90 deg (homes first)
N130 G74 S1                      ; homing beside the path: no wait
N140 G1 Z20
N150 M30                         ; S1 is positioned and stays; S2 is stopped
