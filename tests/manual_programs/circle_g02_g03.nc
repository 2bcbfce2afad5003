; TF5200 manual: Circular interpolation (G02/G03) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206089483.html
; own equivalent: circles by centre point (G162, I/J/K relative to the start)
; in each plane with the plane's pair of centre words
N10 G17 G90 G00 X0 Y0 Z0
N20 G01 X20 F1500
N30 G02 X40 Y0 I10 J0           ; G17: end X/Y, centre I/J - half circle cw
N40 G03 X60 Y0 I10              ; ccw half circle, J omitted (0)
N50 G02 I-10                    ; full circle (end = start), centre X50
N60 G18                         ; Z-X plane: end Z/X, centre K/I
N70 G02 Z-20 X80 K-10 I10
N80 G19                         ; Y-Z plane: end Y/Z, centre J/K
N90 G03 Y30 Z-20 J15 K0
N100 G17
N110 M30
