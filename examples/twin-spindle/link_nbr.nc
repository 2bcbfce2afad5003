N10 #AX LINK NBR[1, 11=6, 17=6] ;Kopplung über log. Achsnummern
N20 #AX LINK ON[1]
N30 S1000 M3
N40 #AX LINK OFF
N50 M30 ;Programmende
