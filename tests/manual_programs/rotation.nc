; TF5200 manual: Rotate the coordinate system in the plane (#ROTATION ON/OFF) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/207442315.html
; own equivalent: a contour rotated by ANGLE about the point CENTER1/CENTER2
; of the G17 plane; V.G.ROT_ANGLE reads the programmed angle back
N10 G17 G90 G00 X0 Y0
N20 #ROTATION ON [ANGLE=90 CENTER1=10 CENTER2=0]
N30 G01 X30 Y0 F3000            ; rotated 90 deg about X10 Y0: machine X10 Y20
N40 P3 = V.G.ROT_ANGLE          ; 90
N50 #ROTATION OFF
N60 G01 X[P3 / 3] Y20           ; X30 Y20, not rotated
N70 M30
