; Tool nose radius compensation on a lathe (G18: Z X plane, X the face
; axis, diameters under G51). Tool 4: nose radius 0.8 mm, cutting-edge
; position 2 (the theoretical tip P lies 0.8 mm towards -Z and -X of the
; nose centre), offsets measured to P: without compensation P follows the
; programmed points; with G42 the nose centre runs 0.8 mm off the contour
; and P 0.8 mm towards -Z -X of it. The profile, in diameters: chamfer
; 2 x 45 deg from D16 to D20, cylinder D20, a concave fillet R5 up to D30
; at Z-25, a cylinder D40 to Z-40. G42: the tool right of the direction of
; travel, i.e. on the outside when turning towards the chuck; G26: arcs
; round the outside corners. Runs to M30.
%profile_trc
N10 G18 G90 G51 G94 G26 D4
N20 M3 S800
N30 G0 X16 Z5
N40 G42 G1 Z0 F200
N50 X20 Z-2
N60 Z-20
N70 G2 X30 Z-25 R5
N80 G1 X40
N90 Z-40
N100 G40 G1 X50
N110 G0 X60 Z5
N120 M5
N130 M30
