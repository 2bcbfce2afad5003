; TF5200 manual: Simple helical interpolation - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206109707.html
; own equivalent: one counter-clockwise helix turn about the absolute centre
; (G161) with the third main axis as helix axis
N10 G17 G90 X-15 Y0 Z-30 F600 G161
N20 G03 I0 J0 Z-12               ; full turn about X0 Y0, Z rises by 18 mm
N30 G162                         ; centre words relative again
N40 M30
