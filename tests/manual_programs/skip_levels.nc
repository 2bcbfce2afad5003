; TF5200 manual: Extended skipping (skip levels) - https://infosys.beckhoff.com/content/1033/tf5200_skipping_of_nc_blocks/214611467.html
; own equivalent: blocks with skip marks /, /1 ... /10; no skip level is set
; (skip mask 0), so every one of them runs
N10 G00 X0 Y0
/ N20 G00 X10                   ; = /1
/3 N30 G00 Y20
/7 N40 G00 X70
/10 N50 G00 Y100
N60 M30
