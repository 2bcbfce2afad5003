; Lathe example: the profile of turn.nc programmed in diameters (G51,
; docs/nc-language.md). X words are diameters (x.lis: kenngr.durchm_prog_abs 1), R stays a
; radius; the trace shows the same radii as turn.nc. Runs to M30.
%diameter
N10 G18 G90 G51
N20 G0 X60 Z2
N30 G1 Z0 F300
N40 G1 X0 F150          ; face to the turning centre
N50 G0 Z2
N60 G0 X20
N70 G1 Z-20 F250
N80 G2 X40 Z-30 R10     ; R is never a diameter
N90 G1 Z-45
N100 G1 X50
N110 G52                ; radius programming again
N120 G0 X30 Z2
N130 M30
