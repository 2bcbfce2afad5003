; The mill names its C axis C (default_ax_name_of_spindle); #CAX [S, Q]
; gives it another name for this program, #CAX OFF gives the default back.
N10 G17 G90 G0 X0 Y0 Z50
N20 M5
N30 #CAX [S, Q]
N40 G0 Q90
N50 #CAX OFF
N60 #CAX
N70 G0 C120
N80 #CAX OFF
N90 M30
