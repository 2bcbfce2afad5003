; TF5200 manual: Programming examples - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206033419.html
; own equivalent: a named main program with rapid moves, a feed move with
; spindle start (S and M3 in the block), spindle stop and program end
%7
N10 G00 X80 Y60                 ; rapid in X and Y
N20 Z40                         ; G00 stays active
N30 G1 Z10 F4000 S1200 M3       ; spindle cw 1200 rpm, feed move to Z10
N40 Z35                         ; feed move back up
N50 G0 X150 Y120 Z50            ; rapid to the park position
N60 M5                          ; spindle stop
N70 M30
