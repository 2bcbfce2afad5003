; Tool radius compensation (G41/G42, D1: radius 5 mm) on three contours
; programmed on the part outline:
;  1. the outside of a rectangle 60 x 40, tool left (G41) going clockwise:
;     arcs of the tool radius round the outside corners (G26; under the
;     default G25 the offset lines would meet at sharp corners instead);
;  2. the same rectangle with corners rounded R8: the tool follows at
;     R13 (8 + 5), the transitions are tangent;
;  3. a pocket 60 x 40, tool left (G41) going counter-clockwise inside:
;     the inside corners are intersections of the offset paths.
; Each contour is selected by a G1 line onto its first corner and left by a
; G40 line. Runs to M30.
%contour_trc
N10 G17 G90 G71 G26 D1
N20 G0 X-20 Y-20 Z2
N30 G1 Z-2 F600
; 1. rectangle, outside
N40 G41 G1 X0 Y0
N50 Y40
N60 X60
N70 Y0
N80 X0
N90 G40 G1 X-20 Y-20
; 2. rounded rectangle, outside
N110 G41 G1 X0 Y8
N120 Y32
N130 G2 X8 Y40 R8
N140 G1 X52
N150 G2 X60 Y32 I0 J-8
N160 G1 Y8
N170 G2 X52 Y0 I-8 J0
N180 G1 X8
N190 G2 X0 Y8 I0 J8
N200 G40 G1 X-20 Y-20
N210 G0 Z2
; 3. pocket 60 x 40, inside
N300 G0 X30 Y20
N305 G1 Z-2
N310 G41 G1 Y0
N320 X60
N330 Y40
N340 X0
N350 Y0
N360 X30
N370 G40 G1 Y20
N380 G0 Z10
N390 M30
