; Mill example: a rounded rectangular pocket contour, a helix, a bolt-hole
; circle from a loop, and a dwell. Runs to M30.
%L HOLE
  G0 Z2
  G1 Z-3 F300
  G4 X0.2              ; dwell 0.2 s at the bottom
  G0 Z2
M17

%contour
#VAR
  V.L.I = 0              ; hole counter
#ENDVAR
N10 G17 G90 G71
N20 G0 X0 Y0 Z10
N30 P1 = 40            ; pocket half width
N40 P2 = 25            ; pocket half height
N50 P3 = 8             ; corner radius
N60 G0 X[P1 - P3] Y[-P2] Z2
N70 G1 Z-2 F500
N80 G1 X[-P1 + P3] F1200
N90 G2 X[-P1] Y[-P2 + P3] I0 J[P3]
N100 G1 Y[P2 - P3]
N110 G2 X[-P1 + P3] Y[P2] I[P3] J0
N120 G1 X[P1 - P3]
N130 G2 X[P1] Y[P2 - P3] I0 J[-P3]
N140 G1 Y[-P2 + P3]
N150 G2 X[P1 - P3] Y[-P2] R[P3]
N160 G0 Z5
; helix: one full turn down 3 mm around X0 Y0
N170 G0 X15 Y0
N180 G1 Z0 F600
N190 G3 X15 Y0 Z-3 I-15 J0 F900
N200 G0 Z10
; bolt-hole circle: six holes on a 30 mm radius
N220 $WHILE V.L.I < 6
N230   G0 X[30 * COS[V.L.I * 60]] Y[30 * SIN[V.L.I * 60]]
N240   LL HOLE
N250   V.L.I = V.L.I + 1
N260 $ENDWHILE
N270 G91 G0 Z20        ; incremental retract
N280 G90 G0 X0 Y0
N290 M30
