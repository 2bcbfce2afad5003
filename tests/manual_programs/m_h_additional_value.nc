; TF5200 manual (TwinCAT CNC programming manual): M/H functions with optional additional information - https://infosys.beckhoff.com/content/1033/tccncprogramming/15556839051.html
; own equivalent in channel syntax: M and H functions with an additional
; value, given directly, negative, by a parameter or by an expression (this
; mill defines M8, M9, M10 in m_synch[]; H functions need no entry)
%m_h_values
N10 M8=-512
N20 M9=64
N35 P1 = 750 P2 = 128
N40 M10=P1
N50 M8=-P2 M9=[P2*3]
N110 H4=-77
N120 H6=P1
N130 H7=[P1 + P2]
N140 M30=0                      ; program end with a value (no output)
