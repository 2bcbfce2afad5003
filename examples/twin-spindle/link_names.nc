N10 #SET AX LINK[1, S2=S, S3=S] ;Hauptspindel ist Master für S2+S3
N20 #ENABLE AX LINK[1] ;Anwahl der Spindelkopplungen
N30 S1000 M3 ;Hauptspindel S+S2+S3 drehen cw 1000 U/min
N40 #DISABLE AX LINK ;Abwahl der Spindelkopplungen
N50 M30 ;Programmende
