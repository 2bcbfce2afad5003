; A G code nck does not know on line 4: the decoder's error 920005 stops
; the channel once the blocks before it have run (N10 reaches X10).
N10 G17 G90 G0 X10
N20 G777 X5
N30 M30
