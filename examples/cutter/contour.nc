; Cutter example: a 500 mm contour at F6000 over a sheet tilted 1 degree and
; wavy (+-2 mm every 200 mm), the torch 1.5 mm above it under 3D distance
; control; frozen over a slot at X 40..60, lifted and switched off at the end.
N10 G17 G90 G71
N20 G0 X0 Y0 Z1.5                    ; programmed 1.5 mm above the nominal sheet (Z 0)
N30 #DIST CTRL ON [SURFACE SET_POS=0]
N40 G4 X0.5                          ; let the control settle on the sheet
N50 G1 X38 F6000
N60 #DIST CTRL FREEZE                ; the slot: hold the height
N70 G1 X62
N80 #DIST CTRL ON                    ; SET_POS is still known
N90 G1 X200
N100 G1 Y100
N110 G1 X100
N120 G1 Y0                           ; 38 + 24 + 138 + 100 + 100 + 100 = 500 mm
N130 #DIST CTRL FREEZE               ; hold the offset while lifting
N140 G0 Z30
N150 #DIST CTRL OFF                  ; travel the offset out in the air
N160 M30
