; Homing on home cams (examples/mill-analog: conventional drives, the NC
; searches each axis's cam, kenngr.homing.homing_type CNC_CONTROLLED):
; Z first, upwards, then X and Y together, towards negative. Each cam's
; edge becomes pos_refpkt (0); the axes end there, then move to the part.
; (The dry run's cams sit at pos_refpkt: N10 puts the axes off them.)
N10 G90 G0 X30 Y20 Z-10
N20 G74 Z1 X2 Y2
N30 G0 X20 Y10
N40 G0 Z5
N50 M30
