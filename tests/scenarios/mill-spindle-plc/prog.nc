; The main spindle S1 with M3 (PLC_INFO MVS_SVS): the next block waits for
; the PLC acknowledgement and for speed reached. spindle.plc sets the S1
; override to 50 %; S[G167] lifts it for one speed.
N10 G17 G90 G0 X0 Y0 Z10
N20 S1000 M3
N30 G1 X50 F3000
N40 S[G167]
N50 G4 X1
N60 S3000
N70 G4 X1
N80 M5
N90 M30
