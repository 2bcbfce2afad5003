; TF5200 manual: Defining a machining coordinate system (#CS DEF, #CS ON/OFF) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/208480907.html
; own equivalent: a CS defined and stored, one with gaps marked by commas,
; one in abbreviated form (translation only), selected and deselected
N10 G90 G00 X0 Y0 Z0
N20 #CS DEF [2] [20, 10, 0, 0, 0, 0]    ; store CS 2: offset X20 Y10
N30 #CS ON [,,-10,,,90]                 ; define + select: Z-10, rotated 90 deg about Z
N40 G01 X10 Y0 Z0 F3000                 ; machine X0 Y10 Z-10
N50 #CS OFF
N60 #CS ON [2]                          ; the stored CS 2
N70 G01 X5 Y5 Z0                        ; machine X25 Y15 Z0
N80 #CS OFF
N90 #CS ON [0, 0, -20]                  ; abbreviated: translation only
N100 G01 X0 Y0 Z0                       ; machine Z-20
N110 #CS OFF
N120 M30
