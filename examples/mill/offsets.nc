; Mill example: the offset chain from program to machine coordinates.
; G54 zero offset, tool length D1, a G92 shift, a rotated coordinate system
; and #ROTATION, #PSET, #SUPPRESS OFFSETS. Runs to M30.
%offsets
N10 G17 G90 G360 G0 X0 Y0 Z0     ; machine zero (G53 is active); G360: every
                                  ; block ends at standstill, so its end point shows
N20 G54                           ; G54: X100 Y50 Z-150 (zero.lis)
N30 D1                            ; tool length 100 mm on Z (tools.lis)
N40 G0 X0 Y0 Z50                  ; MCS X100 Y50 Z0 (-150 + 100 + 50)
N50 G92 X10                       ; additive offset: X0 is now 10 mm further on
N60 G1 X0 F2000                   ; MCS X110
N70 G92 X0                        ; G92 off again
N80 G0 X0                         ; MCS X100
N90 #CS ON [1][20,0,0,0,0,90]     ; a CS 20 mm along X, turned 90 deg about Z
N100 G1 X10 Y0 F2000              ; MCS X120 Y60
N110 G2 X0 Y10 I-10 J0            ; a quarter circle in the turned CS
N120 #CS OFF
N130 #ROTATION ON [ANGLE=45]      ; turn the contour in the plane
N140 G1 X20 Y0                    ; MCS X 114.142 Y 64.142
N150 #ROTATION OFF
N160 G0 X0 Y0
N170 #PSET X5                     ; the current X now reads 5
N180 G1 X15                       ; 10 mm on: MCS X110
N190 #PRESET
N200 #SUPPRESS OFFSETS [ZERO] X0 Y0   ; to the tool-only position (G54 left out)
N210 G53 D0 G0 X0 Y0 Z0          ; back to machine zero
N220 M30
