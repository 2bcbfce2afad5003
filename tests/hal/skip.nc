; issue 46: the block-skip levels and the spindle's orient pin through HAL
; (hal_test.py skip): with nck.channel.1.skip-mask 1 the /1 block is skipped,
; X never goes beyond 10; after M19 nck.spindle.S1.orient is on.
N10 M3 S1000
/N20 G0 X50
N30 G0 X10
N40 S.POS=90 M19 S400
N50 G4 X0.2
N60 M30
