; TF5200 manual: Zero offsets (G53/G54/...G59) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206487307.html
; own equivalent: a zero offset written through V.G.NP[..], selected with
; G54 (group 1), and G54 in G91 mode, which moves nothing until the next
; absolute position
V.G.NP[1].V.X = 35              ; zero offset group 1, X 35 mm
V.G.NP[1].V.Y = -5
G54                             ; select it
G0 X=20 Y=10                    ; machine X55 Y5
G53 G0 X0 Y0                    ; no offset
N10 G54
N20 G0 X0 G91                   ; relative 0: no motion
N30 G90 X0 Y0                   ; absolute: machine X35 Y-5
M30
