; issue 46: G33 with the spindle encoder's index through HAL (hal_test.py
; thread-index): each pass asks the encoder to reset at its next index
; (nck.spindle.S1.index-enable) and starts on that zero mark.
N10 M3 S300
N20 G4 X0.5
N30 G0 X0 Y0 Z5
N40 G33 Z-5 K1       ; 1st pass: 10 turns
N50 G0 Z5
N60 G33 Z-5 K1       ; 2nd pass in the same groove
N70 G0 Z5
N80 M5
N90 M30
