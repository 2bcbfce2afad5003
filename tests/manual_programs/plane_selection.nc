; TF5200 manual: Selection of planes (G17/G18/G19) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206253067.html
; own equivalent: the same quarter circle by radius in each of the three
; planes; the target point and R follow the plane's axis pair
N10 G90 G00 X0 Y0 Z0
N20 G17 G02 X25 Y-25 R25 F2000  ; X-Y plane
N30 G18 G03 Z-25 X50 R25        ; Z-X plane
N40 G19 G02 Y-50 Z-50 R25       ; Y-Z plane
N50 G17
N60 M30
