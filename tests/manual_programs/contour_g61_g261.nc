; TF5200 manual: Example (contouring) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/475259787.html
; own equivalent: #CONTOUR MODE [DEV PATH_DEV=..] parameterises, G61 blends
; the corner at the end of its own block, G261/G260 switch blending for
; every block; a $FOR loop with block numbers from a parameter (N P..) runs
; star-shaped corners
#CONTOUR MODE [DEV PATH_DEV=0.2]
P100 = 40
F6000
N10 G01 X-P100 Y0 Z0
$FOR P123 = 0, 60, 20
  N2 G01 X0 Y0 Z0 G61
  P1 = COS[P123]*P100
  P2 = SIN[P123]*P100
  NP123 XP1 YP2
  N100 G01 X-P100 Y0 Z0
$ENDFOR
G261
N200 X0 Y-30
N210 X30
N220 G260 Y0
M30
