; Mill example: coordinate systems. #CS ADD/SELECT builds a chain, #ACS
; corrects a skewed fixture, #MCS ON runs in machine coordinates for a moment
; and restores everything at OFF. Runs to M30.
%coordinates
N10 G17 G90 G54 G0 X0 Y0 Z50          ; G54: X100 Y50 Z-150
N20 #ACS ON [1][0,0,0,0,0,2]          ; the fixture is turned 2 deg about Z
N30 #CS ADD [PART][20,10,0,0,0,0]     ; a part 20/10 mm from the fixture origin
N40 #CS ADD [HOLE][5,5,0,0,0,90]      ; a feature on it, turned 90 deg
N50 #CS SELECT [HOLE]
N60 G1 X10 Y0 F2000                   ; 10 mm along the feature's X
N70 #CS SELECT [PART]
N80 G1 X0 Y0
N90 #MCS ON                           ; machine coordinates: no offset acts
N100 G0 Z0                            ; machine Z0
N110 #MCS OFF                         ; the CS chain and G54 are back
N120 G0 Z50
N130 #CS OFF ALL
N140 #ACS OFF
N150 G0 X0 Y0
N160 M30
