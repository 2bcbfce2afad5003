; CiA 402 spindle S1 (s1.lis: speed-controlled, position feedback): the
; drive's mode of operation follows the spindle (`drive` events):
;   G74   drive-controlled homing: homing mode (6), the drive homes itself
;   M3    turning: cyclic synchronous velocity (9)
;   M19   positioning: cyclic synchronous position (8), then M3 back to 9
%spindle_modes
N10 G74 S1                     ; the drive homes (homing mode 6)
N20 G4 X0.2                    ; (homing runs beside the program)
N30 M3 S1000                   ; velocity mode
N40 G4 X0.5
N50 S.POS=90 M19 S400          ; position mode: S1 to 90 deg
N60 G4 X0.5
N70 M3 S500                    ; velocity mode again
N80 G4 X0.5
N90 M5
N100 M30
