; issue 46 (e): an operator's actions through HAL pins: feedhold at the
; start, the feed override, cycle start after M0.
N10 G0 X10
N20 M0
N30 G1 X20 F600
N40 M30
