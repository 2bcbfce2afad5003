; Homing on home cams (examples/mill-analog: conventional drives, the NC
; searches each axis's cam, kenngr.homing.homing_type CNC_CONTROLLED):
; Z first, upwards, then X and Y together, towards negative. Each cam's
; edge becomes pos_refpkt (0); the axes end there, then move to the part.
N10 G74 Z1 X2 Y2
N20 G90 G0 X20 Y10
N30 G0 Z5
N40 M30
