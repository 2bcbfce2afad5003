; Mill example: the main spindle S1 in DIN syntax and S2 in spindle syntax.
; S1's M3 is output to the PLC and the motion waits for its acknowledgement
; and for speed reached (m3_synch PLC_INFO MVS_SVS); S2 (MVS_SVS) waits for
; speed reached only. With spindle.plc (S1 override 50 %), the seed's
; override example: 1000 rpm runs at 500, G167 lifts the override (1000),
; the next speed is overridden again (3000 -> 1500).
%spindle
N10 G17 G90 G0 X0 Y0 Z10
N20 S1000 M3                     ; S1 to 1000 rpm (500 at 50 %); the next motion waits
N30 G1 X50 F3000
N40 S2[M4 REV3000]               ; S2 (sensorless) counter-clockwise, 3000 rpm: drive value -32767
N50 G1 Y30
N60 G4 X1
N70 S[G167]                      ; override off for this speed: 1000 rpm
N80 G4 X1
N90 S3000                        ; override acts again: 1500 rpm at 50 %
N100 G1 X0 Y0
N110 S2[M5]                      ; S2 stops
N120 S.POS=90 M19 S400           ; S1 positions to 90 deg (homes first)
N130 G74 S1                      ; homing beside the path: no wait
N140 G1 Z20
N150 M30                         ; S1 is positioned and stays; S2 is stopped
