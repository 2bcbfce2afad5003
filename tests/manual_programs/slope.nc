; TF5200 manual: Selecting operating mode (#SLOPE, #SLOPE DEFAULT) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/207190411.html
; own equivalent: the acceleration profile by type, with NO_OPT=1 (the
; default), the older #SET SLOPE PROFIL[n], and back to the channel's
; default profile (P-CHAN-00071)
N10 G90 G01 X0 Y0 F5000
N20 #SLOPE[TYPE=TRAPEZ]
N30 G01 X40 Y40                 ; trapezoidal acceleration
N40 #SLOPE [TYPE=SIN2 NO_OPT=1]
N50 X80                         ; sine-square
N60 #SET SLOPE PROFIL[1]        ; trapezoidal, older command
N70 Y0
N80 #SLOPE DEFAULT
N90 X0
N100 M30
