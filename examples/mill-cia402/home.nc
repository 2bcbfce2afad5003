; Homing on CiA 402 drives (examples/mill-cia402, kenngr.homing.homing_type
; DRIVE_CONTROLLED): each drive homes itself in mode 6 while its axis
; stands; its position then is the axis's, and G74 moves to pos_refpkt (0).
N10 G90 G0 X120 Y80 Z10
N20 G74 Z1 X2 Y2
N30 G0 X20 Y10
N40 M30
