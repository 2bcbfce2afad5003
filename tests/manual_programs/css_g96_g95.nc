; TF5200 manual: Constant cutting speed at feedrate per revolution (G96, G95) - https://infosys.beckhoff.com/content/1033/tf5200_turning_functions/400190603.html
; own equivalent (lathe, X face-turning axis): G196 limits the speed before
; G96 is selected, G95 feeds per revolution, the spindle speed rises as X
; gets smaller; G97 and G94 deselect
N10 M03 S1200 G01 X50 Z20 F1200
N20 G196 S2200                  ; max. speed 2200 rpm
N25 G95 F0.25                   ; 0.25 mm per revolution
N30 G96 S120                    ; 120 m/min cutting speed
N40 Z0
N50 X12                         ; facing towards the centre
N60 G00 Z2
N70     X50                     ; rapid
N80     Z-1
N90 G01 X12
N100 G97                        ; speed stays as it was last
N110 G94                        ; feed in mm/min again
N115 G00 Z20
N120 M30
