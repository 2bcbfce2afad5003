; TF5200 manual: Verification of running condition at loop start ($WHILE) - https://infosys.beckhoff.com/content/1033/tf5200_programming_manual/206940939.html
; own equivalent: the condition is checked at each loop start; the loop
; ends once it is FALSE (here P4 drops to 0.5 or below)
N10 G01 F6000
N90 P4 = 30.0
N100 $WHILE P4 > 0.5
N110   P4 = P4 - 2.5
N115   Y P4
N120 $ENDWHILE
N130 H30=[P4 * 10]              ; -> 0 (30 - 12 x 2.5)
N140 M30
