; Two channels sharing spindles (FCT-S1 2.2.5.2) with a spindle link,
; channel 1: S3 (known only here) follows the main spindle S (= S2).
%link_ch1
N10 #SET AX LINK[1, S3=S]    ; S3 slave of the main spindle S2
N20 #ENABLE AX LINK[1]
N30 S1000 M3                 ; S2 and S3 turn at 1000 rpm
N40 G90 G1 X20 F1200         ; one second of path while channel 2 runs S1
N50 M5                       ; S2 and S3 stop
N60 #DISABLE AX LINK[1]
N70 S1[M3 REV300]            ; S1 is not linked: either channel may command it
N80 #TIME 0.3
N90 S1[M5]
N100 M30
