; Mill example: corner blending (G261 with #CONTOUR MODE). A 20 mm square
; at F1200; each 90-degree corner gets a circular fillet that stays within
; PATH_DEV = 0.05 mm of the programmed corner, so the path runs through the
; corners at about 17 mm/s instead of slowing to 0.5 mm/s.
%contour_blend
N10 G17 G90 G71
N20 G0 X0 Y0 Z2
N30 G1 Z-1 F300
N40 #CONTOUR MODE [DEV PATH_DEV=0.05]
N50 G261 G1 X20 F1200
N60 Y20
N70 X0
N80 Y0
N90 G260 X-20
N100 G0 Z5
N110 M30
