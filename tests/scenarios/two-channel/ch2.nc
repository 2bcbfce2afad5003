; Channel 2 moves at once.
N10 G90 G0 X-30 Z-10
N20 M30
