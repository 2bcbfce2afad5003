; TF5200 manual: Thread cutting with endlessly rotating spindle (G33) - https://infosys.beckhoff.com/content/1031/tf5200_spindle/400186379.html
; own equivalent (lathe, Z longitudinal, X infeed): a longitudinal thread
; with pitch K in two passes on the zero mark, then a second start of a
; two-start thread shifted by S.OFFSET=180; G00 ends G33
%thread_cut
N10 G18 G90
N20 M3 S500
N30 G0 X30 Z4
N40 G1 X28.8 F400
N50 G33 Z-24 K1.5               ; 500 rpm x 1.5 mm
N60 G0 X30
N70 Z4
N80 G1 X28.4
N90 G33 Z-24 K1.5
N100 G0 X30
N110 Z4
N120 G1 X28.4
N130 G33 Z-24 K1.5 S.OFFSET=180 ; second start, half a turn later
N140 G0 X30
N150 Z4
N160 M5
N170 M30
