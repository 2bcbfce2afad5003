; Mill example: tool offsets. D selects the tool length (on Z in G17); under
; G91 a new offset waits for the next absolute position (G91 rule); #TLC
; adds a length correction. Runs to M30.
%tools
N10 G17 G90 G360 G0 X0 Y0 Z0      ; no tool: machine Z0; G360 exact stop at each end
N20 D1                            ; 100 mm tool: acts at the next absolute Z
N30 G0 Z0                         ; machine Z100
N40 G91 D2                        ; 125 mm drill, incremental mode ...
N50 G0 Z-10                       ; ... Z moves 10 mm, the new length waits: Z90
N60 G90 G0 Z-10                   ; absolute: machine Z -10 + 125 = 115
N70 #TLC ON [0.5]                 ; the tool is 0.5 mm longer than assumed
N80 G0 Z-10                       ; machine Z115.5
N90 #TLC OFF
N100 D0 G0 Z0                     ; no tool again: machine Z0
N110 M30
