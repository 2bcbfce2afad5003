; TF5200 manual: Tool radius compensation (TRC) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/207729163.html
; own equivalent: D1 (radius 5 mm) selected, TRC left of the contour (G41)
; with a linear selection block, linear transitions at outer corners (G25),
; deselection with G40 on a linear block; then right of the contour (G42)
; with circular transitions (G26)
N10 G17 G90 F2000
N20 D1 G25
N30 G00 X-20 Y-20 Z0
N40 G41 G01 X0 Y0               ; selection block
N50 Y40
N60 X60
N70 Y0
N80 X0
N90 G40 G01 X-20 Y-20           ; deselection block
N100 G42 G26 G01 X0 Y0
N110 X60
N120 Y40
N130 G02 X40 Y60 R20
N140 G01 X0
N150 G40 X-20 Y-20
N160 M30
