; Mill example: a G100 measuring run, the measured value in V.A.MESS.Z, and
; the G101 measuring offset. The probe (sim.lis) switches at machine Z -123.
; With G54 (Z -150) and D1 (length 100) the PCS Z of the switching point is
; -123 + 150 - 100 = -73; the target was -80, so V.A.MOFFS.Z = 7.
%measure
N10 G17 G90 G360 G54 D1 G0 X0 Y0 Z-50 ; G360: exact stop at every block end
N20 G100 Z-80 F300                 ; stops where the probe switches
N30 P1 = V.A.MESS.Z                ; -73
N40 G101 Z1                        ; measuring offset (-73 - -80) * 1 = 7 mm on Z
N50 G0 Z[P1]                       ; PCS -73 now lies 7 mm higher: MCS Z -116
N60 G102                           ; offset off again
N70 G0 Z0
N80 M30
