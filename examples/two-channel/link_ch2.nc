; Two channels sharing spindles (FCT-S1 2.2.5.2) with a spindle link,
; channel 2: S1 is known to both channels and not linked, so channel 2 may
; command it while channel 1's link of S2 and S3 is enabled.
%link_ch2
N10 #TIME 0.2
N20 S1[M4 REV600]
N30 G90 G1 X-10 F1200
N40 S1[M5]
N50 M30
