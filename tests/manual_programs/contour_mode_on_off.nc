; TF5200 manual: Activating contouring modes in the NC program - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/475156491.html
; own equivalent: #CONTOUR MODE ON [DEV PATH_DEV=..] parameterises and
; selects corner blending (= G261), #CONTOUR MODE OFF deselects it (= G260)
%blend_on_off
N10 G90 G01 X0 Y0 Z0 F2400
N20 #CONTOUR MODE ON [DEV PATH_DEV=0.5]
N30 X80
N40 Y60
N50 X0
N60 Y0
N70 #CONTOUR MODE OFF
N75 X20
N80 M30
