; #CAX [S, <name>] on a channel without default_ax_name_of_spindle: the
; C axis takes the name the program gives it, here Q and then C1 (a name
; of more than one letter takes "="), and #FACE takes that name too.
N10 G17 G90 G0 X20 Y0 Z50
N20 M5                      ; C-axis mode needs the spindle at standstill
N30 #CAX [S, Q]
N40 G0 Q90
N50 #CAX OFF
N60 #CAX [S, C1]
N70 G1 C1=180 F36000        ; C alone: 180 deg at 600 deg/s
N80 #FACE [X, C1]
N90 G1 X30 C1=0 F600        ; on the face: the tool at X30, C (mm) 0
N100 #FACE OFF
N110 G0 C1=270
N120 #CAX OFF
N130 M30
